// SPDX-License-Identifier: MIT
// MRPT's deserialiser trusts the sizes a rawlog claims: a few flipped bytes can make it
// allocate without end or loop. read_mrpt_rawlog() therefore runs the reader below in a
// child process with an address-space and a CPU-time limit per file and takes the log back
// through a socket; a child that breaks a limit or crashes becomes a ParseError naming the
// file and is replaced at the next read. The child is forked once and serves the reads that
// follow, so reading many files costs one fork, not one per file.
#pragma once

#include <cstdint>
#include <string>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::slam::detail {

/// The reader itself, in this process (mrpt_rawlog_reader.cpp).
LaserLog read_mrpt_rawlog_unguarded(const std::string& path, const LogReadOptions& options);

/// The child's limits for a file of `file_bytes`: memory 64x the file on top of what the
/// child already maps, at least 64 MB (never over what the machine has); CPU time 10 s per
/// MB, at least 60 s.
struct RawlogLimits {
  std::uint64_t memory_bytes = 0;
  std::uint64_t cpu_seconds = 0;
};
RawlogLimits rawlog_limits(std::uint64_t file_bytes);

}  // namespace lookahead::slam::detail
