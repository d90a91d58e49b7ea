// SPDX-License-Identifier: MIT
#include "costmap_checkers.hpp"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>

#include "segment_walk.hpp"

namespace lookahead::planner::detail {
namespace ob = ompl::base;
namespace {

Point2 position(const ob::State* state) {
  const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
  return {v[0], v[1]};
}

}  // namespace

bool CostmapValidityChecker::isValid(const ob::State* state) const { return costmap_.is_free(position(state)); }

bool CostmapMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const {
  const bool ok = costmap_.segment_is_free(position(s1), position(s2));
  (ok ? valid_ : invalid_)++;
  return ok;
}

bool CostmapMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                         std::pair<ob::State*, double>& last_valid) const {
  const Point2 a = position(s1);
  const Point2 b = position(s2);
  const double res = costmap_.resolution();
  double blocked_at = 1.0;
  const bool ok = walk_segment(a.x / res, a.y / res, b.x / res, b.y / res, [&](int x, int y, double t) {
    if (costmap_.cell_is_free({x, y})) return true;
    blocked_at = t;
    return false;
  });
  if (!ok) {
    // Step back a little from the blocked cell's border so the reported state is inside
    // the previous (free) cell.
    last_valid.second = std::max(0.0, blocked_at - 1e-6);
    if (last_valid.first != nullptr) {
      si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
    }
  }
  (ok ? valid_ : invalid_)++;
  return ok;
}

}  // namespace lookahead::planner::detail
