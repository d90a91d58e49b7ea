// SPDX-License-Identifier: MIT
// The picture of a SegSLAM run a person can read (as Fairfield et al. 2010, Fig. 12 right):
// the map, the raw odometry, the reconstructed trajectory with one colour per submap, and
// an X where a particle re-entered an old submap (a match).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::slam::segslam {

struct SegmentedPath {
  std::vector<std::vector<Pose2>> pieces;          ///< one per submap of the chain, in order
  std::vector<std::pair<double, double>> matches;  ///< where the chain re-entered a submap [m]
  /// What the pieces are, for the legend.
  std::string label = "SegSLAM trajectory, one colour per submap";
};

void write_segment_picture(const std::string& png_path, const ProbabilityMap& map, const std::vector<Pose2>& odometry,
                           const SegmentedPath& path, const std::string& title);

}  // namespace lookahead::slam::segslam
