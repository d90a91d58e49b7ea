// SPDX-License-Identifier: MIT
// A laser log as the filter consumes it: scans in time order, each with its odometry pose.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam {

struct LogReadOptions {
  /// Count and skip malformed lines instead of stopping at the first one.
  bool skip_bad_lines = false;
  /// Readings at or above this are no-returns even where the log claims a larger max range
  /// (CARMEN logs write 81.83/81.91 for "no echo") [m].
  double no_return_range = 80.0;
};

struct LaserLog {
  std::string path;
  std::vector<LaserScan> scans;
  std::size_t lines_read = 0;
  std::size_t bad_lines = 0;            ///< skipped with --skip-bad-lines
  std::string first_bad_line_message;   ///< what was wrong with the first skipped line
};

/// Reads a CARMEN log (.log/.clf, or the same gzip-compressed with .gz).
LaserLog read_carmen_log(const std::string& path, const LogReadOptions& options = {});
/// Reads an MRPT .rawlog through MRPT's own deserialisation.
LaserLog read_mrpt_rawlog(const std::string& path, const LogReadOptions& options = {});
/// Chooses the reader by the file's extension (.rawlog -> MRPT, anything else -> CARMEN).
LaserLog read_laser_log(const std::string& path, const LogReadOptions& options = {});

}  // namespace lookahead::slam
