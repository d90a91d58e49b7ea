// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/range_bearing.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam::hybrid {

PredictedObservation predict_observation(const Pose2& pose, const Vector2& point) {
  const double dx = point.x() - pose.x, dy = point.y() - pose.y;
  const double q = std::max(dx * dx + dy * dy, 1e-12);
  const double r = std::sqrt(q);
  PredictedObservation o;
  o.z = {r, normalize_angle(std::atan2(dy, dx) - pose.theta)};
  o.d_pose << -dx / r, -dy / r, 0.0, dy / q, -dx / q, -1.0;
  o.d_point << dx / r, dy / r, -dy / q, dx / q;
  return o;
}

InitialisedPoint point_from_observation(const Pose2& pose, double range, double bearing) {
  const double a = pose.theta + bearing;
  const double c = std::cos(a), s = std::sin(a);
  InitialisedPoint p;
  p.point = {pose.x + range * c, pose.y + range * s};
  p.d_pose << 1.0, 0.0, -range * s, 0.0, 1.0, range * c;
  p.d_z << c, -range * s, s, range * c;
  return p;
}

Vector2 innovation(const RangeBearing& z, const Vector2& predicted) {
  return {z.range - predicted.x(), normalize_angle(z.bearing - predicted.y())};
}

Matrix2 range_bearing_noise(double sigma_range, double sigma_bearing) {
  Matrix2 r = Matrix2::Zero();
  r(0, 0) = sigma_range * sigma_range;
  r(1, 1) = sigma_bearing * sigma_bearing;
  return r;
}

}  // namespace lookahead::slam::hybrid
