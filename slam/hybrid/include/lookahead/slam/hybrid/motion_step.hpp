// SPDX-License-Identifier: MIT
// One control step for the Gaussian filters: the increment u = (dx, dy, dtheta) in the frame
// of the previous pose, with independent noise per component, and the Jacobians of
// x (+) u. Simulated velocities (v dt, 0, omega dt) and real odometry increments both fit.
#pragma once

#include <Eigen/Core>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::hybrid {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

struct MotionStep {
  Pose2 delta;                      ///< u
  Vector3 sigma = Vector3::Zero();  ///< std of u's components [m, m, rad]
  double dt = 0.1;                  ///< duration [s]
};

struct MotionJacobians {
  Matrix3 d_pose;  ///< d(x (+) u) / dx
  Matrix3 d_u;     ///< d(x (+) u) / du
};

MotionJacobians motion_jacobians(const Pose2& pose, const Pose2& u);

/// Covariance of the predicted pose due to the control noise alone: J_u Q J_u^T.
Matrix3 control_covariance(const Pose2& pose, const MotionStep& step);

/// Pose <-> vector (x, y, theta).
inline Vector3 to_vector(const Pose2& p) { return {p.x, p.y, p.theta}; }
Pose2 to_pose(const Vector3& v);

}  // namespace lookahead::slam::hybrid
