// SPDX-License-Identifier: MIT
// Travel cost from the robot to every reachable cell: Dijkstra over 8-connected traversable
// cells (steps of 1 and sqrt 2 cells; a diagonal step needs both cells beside it free). One run per target selection
// prices every frontier goal at once, where a planner call per goal would cost a planning budget each.
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "lookahead/slam/grid/cell_index.hpp"

namespace lookahead::exploration {

class TravelCost {
 public:
  /// Distances [m] from `start` over cells in [lo, hi] for which traversable(c) holds
  /// (asked at most once per cell). With `targets`, the search stops once every reachable
  /// target is settled: distances and paths are then exact for the targets and for the cells
  /// nearer than the farthest of them; other cells may read too far or unreachable. A replan
  /// needs one goal, not the whole building (on a 134 m plan the full search was 30 % of a
  /// mission's time).
  TravelCost(slam::CellIndex lo, slam::CellIndex hi, double resolution, slam::CellIndex start,
             const std::function<bool(slam::CellIndex)>& traversable, const std::vector<slam::CellIndex>& targets = {});

  /// Distance to a cell [m]; infinity when unreachable or outside the bounds.
  [[nodiscard]] double at(slam::CellIndex c) const;
  [[nodiscard]] bool reachable(slam::CellIndex c) const { return at(c) < kInfinity; }
  /// The cells of a shortest path from the start to `c` (start first); empty if unreachable.
  [[nodiscard]] std::vector<slam::CellIndex> path_to(slam::CellIndex c) const;

  static constexpr double kInfinity = std::numeric_limits<double>::infinity();

 private:
  [[nodiscard]] int index(slam::CellIndex c) const;
  slam::CellIndex lo_, hi_;
  int width_ = 0, height_ = 0;
  std::vector<float> dist_;
  std::vector<int> parent_;  ///< index of the cell each was reached from, -1 at the start
};

}  // namespace lookahead::exploration
