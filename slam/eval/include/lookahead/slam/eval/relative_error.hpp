// SPDX-License-Identifier: MIT
// Relative pose error of Kuemmerle et al., "On measuring the accuracy of SLAM algorithms",
// Autonomous Robots 27, 2009: for each relation (t1, t2, delta) the estimate's own relative
// motion pose(t1)^-1 (+) pose(t2) is compared with delta.
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::slam {

struct Relation {
  double t1 = 0.0;
  double t2 = 0.0;
  Pose2 delta;  ///< pose at t2 in the frame of the pose at t1
};

/// Reads a benchmark .relations file: "t1 t2 x y z roll pitch yaw" per line.
std::vector<Relation> read_relations(const std::string& path);

struct RelativeError {
  double trans_mean = 0.0, trans_std = 0.0;  ///< [m]
  double rot_mean = 0.0, rot_std = 0.0;      ///< [deg]
  std::size_t used = 0;                      ///< relations whose two stamps matched a pose
  std::size_t skipped = 0;                   ///< relations with a stamp farther than the tolerance from any pose
};

/// Matches each relation stamp to the nearest trajectory stamp within `tolerance` seconds.
RelativeError relative_error(const std::vector<Relation>& relations, const std::vector<StampedPose>& trajectory,
                             double tolerance = 0.005);

/// Relations between consecutive-enough poses of a reference trajectory (every pair of
/// reference poses `stride` apart): for logs whose reference is another trajectory.
std::vector<Relation> relations_from_reference(const std::vector<StampedPose>& reference, std::size_t stride = 1);

}  // namespace lookahead::slam
