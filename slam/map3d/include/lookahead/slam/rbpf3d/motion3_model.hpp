// SPDX-License-Identifier: MIT
// The proposal of the 3D RBPF (SegSLAM sec. 2.2), shared by Rbpf3d and SegSlam3d: the
// dead-reckoned increment with noise on x, y, z and yaw; roll and pitch are the IMU's.
#pragma once

#include <random>

#include "lookahead/slam/geometry/pose3.hpp"
#include "lookahead/slam/rbpf3d/rbpf3d_options.hpp"

namespace lookahead::slam {

/// The pose after `increment` (robot frame, from dead reckoning) from `previous`, with the
/// yaw advanced by `odometry_yaw_change` plus noise and the IMU's roll and pitch.
Pose3 sample_motion3(const Pose3& previous, const Pose3& increment, const Euler& imu, double odometry_yaw_change,
                     const Motion3Options& m, std::mt19937_64& rng);

}  // namespace lookahead::slam
