// SPDX-License-Identifier: MIT
// The range-bearing observation of a point feature from a planar pose, its inverse, and the
// Jacobians every filter of HybridSLAM linearises with (Durrant-Whyte & Bailey 2006).
#pragma once

#include <Eigen/Core>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::hybrid {

/// One observation: range [m] and bearing [rad] in the robot frame, with its covariance.
struct RangeBearing {
  double range = 0.0;
  double bearing = 0.0;
  Eigen::Matrix2d noise = Eigen::Matrix2d::Identity();
};

using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;
using Matrix23 = Eigen::Matrix<double, 2, 3>;

struct PredictedObservation {
  Vector2 z;        ///< (range, bearing)
  Matrix23 d_pose;  ///< dz / d(x, y, theta)
  Matrix2 d_point;  ///< dz / d(mx, my)
};

/// h(pose, point).
PredictedObservation predict_observation(const Pose2& pose, const Vector2& point);

struct InitialisedPoint {
  Vector2 point;
  Matrix23 d_pose;  ///< d point / d(x, y, theta)
  Matrix2 d_z;      ///< d point / d(range, bearing)
};

/// h^-1: the point an observation places from `pose`.
InitialisedPoint point_from_observation(const Pose2& pose, double range, double bearing);

/// z - h with the bearing wrapped to (-pi, pi].
Vector2 innovation(const RangeBearing& z, const Vector2& predicted);

/// Sensor noise diag(sigma_range^2, sigma_bearing^2).
Matrix2 range_bearing_noise(double sigma_range, double sigma_bearing);

}  // namespace lookahead::slam::hybrid
