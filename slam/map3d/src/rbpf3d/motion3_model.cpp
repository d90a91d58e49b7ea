// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf3d/motion3_model.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam {

Pose3 sample_motion3(const Pose3& previous, const Pose3& increment, const Euler& imu, double odometry_yaw_change,
                     const Motion3Options& m, std::mt19937_64& rng) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const double travelled = increment.translation().norm();
  const double sigma_xy = std::max(m.min_xy, m.xy_per_metre * travelled);
  const double sigma_yaw =
      std::max(m.min_yaw, m.yaw_per_metre * travelled + m.yaw_per_radian * std::abs(odometry_yaw_change));
  Eigen::Vector3d position = previous * increment.translation();
  position += Eigen::Vector3d(sigma_xy * unit(rng), sigma_xy * unit(rng), m.z_per_metre * travelled * unit(rng));
  const double yaw = euler_of(previous.linear()).yaw + odometry_yaw_change + sigma_yaw * unit(rng);
  return make_pose3(position, {imu.roll, imu.pitch, yaw});
}

}  // namespace lookahead::slam
