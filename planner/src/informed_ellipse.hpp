// SPDX-License-Identifier: MIT
// The informed set of a path-length problem in R^2: Gammell, Srinivasa & Barfoot, "Informed
// RRT*", IROS 2014, Sec. IV. A state x can lie on a path from s to g of length <= c only if
// |x - s| + |x - g| <= c, an ellipse with foci s and g; it is sampled directly (uniform in
// the unit disc, stretched to the ellipse, rotated).
// Deviation: the goal tolerance widens the ellipse (a path may stop that short of g); the
// paper has a point goal.
#pragma once

#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>

#include "lookahead/planner/path.hpp"

namespace lookahead::planner::detail {

class InformedEllipse {
 public:
  InformedEllipse(Point2 start, Point2 goal, double tolerance)
      : centre_{0.5 * (start.x + goal.x), 0.5 * (start.y + goal.y)},
        half_focal_(0.5 * distance(start, goal)),
        angle_(std::atan2(goal.y - start.y, goal.x - start.x)),
        tolerance_(tolerance) {}

  [[nodiscard]] double semi_major(double cost) const { return std::max(0.5 * (cost + tolerance_), half_focal_); }
  [[nodiscard]] double semi_minor(double cost) const {
    const double a = semi_major(cost);
    return std::sqrt(std::max(a * a - half_focal_ * half_focal_, 0.0));
  }
  [[nodiscard]] double area(double cost) const { return M_PI * semi_major(cost) * semi_minor(cost); }

  /// A uniform draw from the ellipse of paths no longer than `cost`.
  [[nodiscard]] Point2 sample(double cost, ompl::RNG& rng) const {
    const double a = semi_major(cost);
    const double b = semi_minor(cost);
    const double r = std::sqrt(rng.uniform01());  // sqrt: uniform in area, not in radius
    const double phi = rng.uniformReal(-M_PI, M_PI);
    const double ex = a * r * std::cos(phi);
    const double ey = b * r * std::sin(phi);
    return {centre_.x + ex * std::cos(angle_) - ey * std::sin(angle_),
            centre_.y + ex * std::sin(angle_) + ey * std::cos(angle_)};
  }

 private:
  Point2 centre_;
  double half_focal_;
  double angle_;
  double tolerance_;
};

}  // namespace lookahead::planner::detail
