// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/motion_step.hpp"

#include <cmath>

#include "lookahead/slam/hybrid/gaussian_map.hpp"

namespace lookahead::slam::hybrid {

MotionJacobians motion_jacobians(const Pose2& pose, const Pose2& u) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  MotionJacobians j;
  j.d_pose << 1.0, 0.0, -s * u.x - c * u.y, 0.0, 1.0, c * u.x - s * u.y, 0.0, 0.0, 1.0;
  j.d_u << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return j;
}

Matrix3 control_covariance(const Pose2& pose, const MotionStep& step) {
  const Matrix3 ju = motion_jacobians(pose, step.delta).d_u;
  return ju * step.sigma.cwiseAbs2().asDiagonal() * ju.transpose();
}

Pose2 to_pose(const Vector3& v) { return {v.x(), v.y(), normalize_angle(v.z())}; }

Pose2 GaussianMap::vehicle() const { return to_pose(mean.head<3>()); }

}  // namespace lookahead::slam::hybrid
