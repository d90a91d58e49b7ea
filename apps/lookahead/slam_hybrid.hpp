// SPDX-License-Identifier: MIT
// `lookahead slam LOG --method hybrid`: HybridSLAM on a real laser log.
#pragma once

#include <string>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::app {

struct SlamHybridArgs {
  std::string out;
  std::string config;   ///< HybridSLAM YAML (config/hybrid/default.yaml format), may be empty
  int particles = -1;   ///< overrides the config when >= 1
  long long seed = -1;  ///< overrides the config when >= 0
};

int run_slam_hybrid(const slam::LaserLog& log, const SlamHybridArgs& args);

}  // namespace lookahead::app
