// SPDX-License-Identifier: MIT
// The robot's own trail, kept as a stack of crumbs: the way back out of a place whose exits
// the costmap has closed since the robot came in. A door whose jambs were still unknown when
// the robot drove through looks wider than it is; once its faces are mapped (range noise
// puts a wall cell into the gap on each side), the safety margin closes it and no plan leads
// out. The trail is known to be passable: the robot drove it.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "lookahead/planner/path.hpp"

namespace lookahead::exploration {

class Breadcrumbs {
 public:
  /// Crumbs are dropped at least `spacing` [m] apart (> 0).
  explicit Breadcrumbs(double spacing = 0.1);

  /// Appends p when it lies at least `spacing` from the last crumb.
  void drop(planner::Point2 p);

  /// The trail back from `from` to the most recent crumb for which `outside` holds, newest
  /// crumb first. The crumbs on it are popped: the robot retraces them, and a later
  /// backtrack starts from where this one ends, never back into the place it left. Empty
  /// (and nothing popped) when no crumb qualifies.
  [[nodiscard]] planner::Path backtrack(planner::Point2 from, const std::function<bool(planner::Point2)>& outside);

  [[nodiscard]] std::size_t size() const { return crumbs_.size(); }

 private:
  double spacing_;
  std::vector<planner::Point2> crumbs_;
};

}  // namespace lookahead::exploration
