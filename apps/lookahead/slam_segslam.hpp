// SPDX-License-Identifier: MIT
// `lookahead slam LOG --method segslam`: the SegSLAM path of the slam command.
#pragma once

#include <cstddef>
#include <string>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::app {

struct SegSlamArgs {
  std::string log;
  std::string out;
  std::string config;          ///< RBPF options (config/slam/default.yaml)
  std::string segslam_config;  ///< SegSLAM options (config/segslam/default.yaml)
  int particles = -1;
  long long seed = -1;
  int threads = -1;
  std::size_t max_scans = 0;
  bool skip_bad_lines = false;
  int map_samples = -1;  ///< overrides offline.map_samples
  slam::BagReadOptions bag;
};

/// Maps the log with SegSLAM and writes map.pgm/.yaml (the minimum-entropy map sample),
/// map.png (segment-coloured trajectory, matches marked), trajectory.txt and run.json.
int run_segslam(const SegSlamArgs& args);

}  // namespace lookahead::app
