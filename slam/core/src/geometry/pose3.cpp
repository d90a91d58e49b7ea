// SPDX-License-Identifier: MIT
#include "lookahead/slam/geometry/pose3.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam {

Pose3 make_pose3(const Eigen::Vector3d& position, const Euler& a) {
  Pose3 p = Pose3::Identity();
  p.linear() =
      (Eigen::AngleAxisd(a.yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a.pitch, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(a.roll, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  p.translation() = position;
  return p;
}

Euler euler_of(const Eigen::Matrix3d& r) {
  Euler a;
  a.pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  a.roll = std::atan2(r(2, 1), r(2, 2));
  a.yaw = std::atan2(r(1, 0), r(0, 0));
  return a;
}

}  // namespace lookahead::slam
