// SPDX-License-Identifier: MIT
// 3D poses: Eigen isometries built from and taken apart into (x, y, z, roll, pitch, yaw),
// with R = Rz(yaw) Ry(pitch) Rx(roll) (x forward, y left, z up).
#pragma once

#include <Eigen/Geometry>

namespace lookahead::slam {

using Pose3 = Eigen::Isometry3d;

struct Euler {
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  ///< [rad]
};

Pose3 make_pose3(const Eigen::Vector3d& position, const Euler& angles);
/// The angles of R = Rz(yaw) Ry(pitch) Rx(roll), pitch in [-pi/2, pi/2].
Euler euler_of(const Eigen::Matrix3d& rotation);

}  // namespace lookahead::slam
