// SPDX-License-Identifier: MIT
// The laser log a command maps: the reader options of the command line (bag topics and
// frames) and the log check run before mapping.
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::app {

/// --scan-topic, --odom-topic, --odom-frame, --base-frame, --laser-frame.
void add_bag_options(CLI::App& app, slam::BagReadOptions& bag);

/// Reads the log, warns about every finding of `lookahead check` that is not a note, and
/// keeps the first `max_scans` scans (0: all). Throws when there is nothing to map.
slam::LaserLog load_laser_log(const std::string& path, const slam::LogReadOptions& read, std::size_t max_scans);

}  // namespace lookahead::app
