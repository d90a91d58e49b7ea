// SPDX-License-Identifier: MIT
#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

double normalize_angle(double a) {
  a = std::remainder(a, 2.0 * M_PI);  // in [-pi, pi]
  return a <= -M_PI ? a + 2.0 * M_PI : a;
}

Pose2 Pose2::compose(const Pose2& o) const {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return {x + c * o.x - s * o.y, y + s * o.x + c * o.y, normalize_angle(theta + o.theta)};
}

Pose2 Pose2::inverse() const {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return {-c * x - s * y, s * x - c * y, normalize_angle(-theta)};
}

Pose2 Pose2::between(const Pose2& o) const { return inverse().compose(o); }

}  // namespace lookahead::slam
