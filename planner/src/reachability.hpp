// SPDX-License-Identifier: MIT
// Exact reachability on the costmap, without sampling. With corner-touching segments counted
// as touching all four cells (segment_walk.hpp), any free polyline moves between
// 4-neighbouring free cells, and 4-neighbouring free cells are joined by the free segment
// between their centres: so a free path exists exactly when a 4-connected flood fill links
// the two cells. plan() uses it to answer "unreachable" at once instead of after the budget.
#pragma once

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path.hpp"

namespace lookahead::planner::detail {

/// Whether a free path can lead from `start` to some position within `tolerance` of `goal`.
/// Conservative for tolerance > 0: answers true if any reachable cell touches that disc.
bool reachable(const Costmap& costmap, Point2 start, Point2 goal, double tolerance);

}  // namespace lookahead::planner::detail
