// SPDX-License-Identifier: MIT
// The robot's own trail, crumbs in the order they were dropped: the way back out of a place
// whose exits the costmap has closed since the robot came in. A door whose jambs were still unknown when
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

  /// Whether the straight way between two points of the trail is open.
  using Passable = std::function<bool(planner::Point2, planner::Point2)>;

  /// The shortest way along the trail from `from` back to the most recent crumb for which
  /// `outside` holds. The trail is the crumbs in the order they were dropped; where it
  /// passed a place more than once, crumbs of different passes within `kLinkRadius` of each
  /// other are joined when `passable` says the straight way between them is open (none are
  /// joined without it). The way starts at the nearest crumb `passable` reaches from
  /// `from` (the newest crumb when none). The crumbs newer than the exit crumb are popped:
  /// a later backtrack starts from where this one ends, never back into the place it left.
  /// Empty (and nothing popped) when no crumb qualifies.
  [[nodiscard]] planner::Path backtrack(planner::Point2 from, const std::function<bool(planner::Point2)>& outside,
                                        const Passable& passable = {});

  /// Passes through one door lie within the door's width of each other.
  static constexpr double kLinkRadius = 0.3;

  [[nodiscard]] std::size_t size() const { return crumbs_.size(); }

 private:
  double spacing_;
  std::vector<planner::Point2> crumbs_;
};

}  // namespace lookahead::exploration
