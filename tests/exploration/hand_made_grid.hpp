// SPDX-License-Identifier: MIT
// Hand-made occupancy grids for the exploration tests: rectangles of evidence, and the
// walled room, open on its right side, that several tests start from; selection inputs over them.
#pragma once

#include "lookahead/exploration/target_selection.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration::testing {

/// Adds `log_odds` (fixed point) to every cell of [x0, x1] x [y0, y1].
inline void add_rect(slam::OccupancyGrid& g, int x0, int y0, int x1, int y1, int log_odds) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) g.add_log_odds({x, y}, log_odds);
}

/// `width` x `height` free cells from (0, 0), walled below, above and on the left; the
/// walls run to x = `wall_end` on the right, the room's right side stays open.
inline slam::OccupancyGrid open_room(int width, int height, int wall_end) {
  slam::OccupancyGrid g;
  add_rect(g, 0, 0, width - 1, height - 1, 3 * g.fixed_miss());
  add_rect(g, -1, -1, wall_end, -1, 3 * g.fixed_hit());
  add_rect(g, -1, height, wall_end, height, 3 * g.fixed_hit());
  add_rect(g, -1, -1, -1, height, 3 * g.fixed_hit());
  return g;
}

/// Selection inputs over a hand-made map, with the small sample budget the tests plan with.
inline SelectionInputs selection_inputs(const slam::OccupancyGrid& map, const planner::Costmap& costmap,
                                        const FrontierDetector& frontiers, const TargetStrategy& strategy,
                                        GoalBlacklist& blacklist, slam::Pose2 pose) {
  SelectionInputs in;
  in.map = &map;
  in.costmap = &costmap;
  in.frontiers = &frontiers;
  in.strategy = &strategy;
  in.blacklist = &blacklist;
  in.pose = pose;
  in.planner.max_samples = 500;
  return in;
}

}  // namespace lookahead::exploration::testing
