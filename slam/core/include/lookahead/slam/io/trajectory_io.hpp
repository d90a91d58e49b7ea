// SPDX-License-Identifier: MIT
// Trajectory text files: one line per scan, "timestamp x y theta" (timestamps as in the log).
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

struct StampedPose {
  double t = 0.0;
  Pose2 pose;
};

void write_trajectory(const std::string& path, const std::vector<StampedPose>& poses);
/// Reads a trajectory file; '#' lines and blank lines are skipped; errors name file:line.
std::vector<StampedPose> read_trajectory(const std::string& path);

}  // namespace lookahead::slam
