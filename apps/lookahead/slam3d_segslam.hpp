// SPDX-License-Identifier: MIT
// `lookahead slam3d INPUT --method segslam`: SegSLAM on octree submaps (slam/segslam/
// seg_slam3d.hpp) over a 3D range log, and its outputs: map.bt (the minimum-entropy map
// sample), trajectory.png (top view, one colour per submap, an X per re-entry),
// trajectory.txt and run.json.
#pragma once

#include <string>

#include "lookahead/slam/rbpf3d/slam3d_config.hpp"
#include "lookahead/slam/sensor/range_sweep.hpp"

namespace lookahead::app {

struct SegSlam3dRun {
  std::string input;           ///< as given on the command line
  std::string name;            ///< short name for titles
  std::string out;             ///< output folder
  std::string segslam_config;  ///< YAML on top of segslam3d_defaults(), may be empty
  int map_samples = -1;        ///< offline samples; -1: the config's offline.map_samples
  long long data_seed = 1;
  /// Cap of the coarse search's widening reach [m] (candidate_reach.hpp); < 0: the default.
  double max_search_radius = -1.0;
  /// Cap of the wide, unambiguous re-entry search [m] (wide_reentry.hpp); 0: off, < 0: the default.
  double wide_reentry_radius = -1.0;
  /// Every particle searches its own copy of a segment (MatchingOptions::share_by_segment off).
  bool search_per_particle = false;
};

/// Runs the filter over `log`, then the offline search, and writes the outputs.
void run_segslam3d(const SegSlam3dRun& run, const slam::RangeLog3& log, const slam::Slam3dOptions& options);

}  // namespace lookahead::app
