// SPDX-License-Identifier: MIT
// Trajectories in the TUM RGB-D benchmark format (Sturm et al. 2012, "A Benchmark for the
// Evaluation of RGB-D SLAM Systems"), which evo reads unchanged: one line per pose,
// "timestamp tx ty tz qx qy qz qw", '#' comments. Planar poses are written with z = 0 and
// a yaw-only quaternion; reading keeps x, y and the yaw (REP 103) of the quaternion.
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::slam {

void write_tum_trajectory(const std::string& path, const std::vector<StampedPose>& poses);
/// Errors name file:line, the field and the value (wrong column count, not a number,
/// a quaternion of norm far from 1).
std::vector<StampedPose> read_tum_trajectory(const std::string& path);
/// TUM or "timestamp x y theta", told apart by the first data line's column count (8 or 4).
std::vector<StampedPose> read_any_trajectory(const std::string& path);
/// True when the first data line of `path` has the eight TUM columns.
bool is_tum_trajectory(const std::string& path);

}  // namespace lookahead::slam
