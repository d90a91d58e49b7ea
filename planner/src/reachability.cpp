// SPDX-License-Identifier: MIT
#include "reachability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lookahead::planner::detail {
namespace {

/// 4-connected flood fill of the free cells from `seed`; 1 marks reached cells (row-major
/// from the costmap's origin).
std::vector<std::uint8_t> flood_fill(const Costmap& costmap, slam::CellIndex seed) {
  const int w = costmap.width();
  const int h = costmap.height();
  const slam::CellIndex o = costmap.origin();
  std::vector<std::uint8_t> reached(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  if (!costmap.cell_is_free(seed)) return reached;
  const auto at = [&](int x, int y) {
    return static_cast<std::size_t>(y - o.y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x - o.x);
  };
  std::vector<slam::CellIndex> stack{seed};
  reached[at(seed.x, seed.y)] = 1;
  constexpr int kDx[4] = {1, -1, 0, 0};
  constexpr int kDy[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const slam::CellIndex c = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const slam::CellIndex n{c.x + kDx[k], c.y + kDy[k]};
      if (!costmap.cell_is_free(n) || reached[at(n.x, n.y)]) continue;
      reached[at(n.x, n.y)] = 1;
      stack.push_back(n);
    }
  }
  return reached;
}

}  // namespace

bool reachable(const Costmap& costmap, Point2 start, Point2 goal, double tolerance) {
  const std::vector<std::uint8_t> reached = flood_fill(costmap, costmap.cell_at(start));
  const slam::CellIndex o = costmap.origin();
  const double res = costmap.resolution();
  const slam::CellIndex lo = costmap.cell_at({goal.x - tolerance, goal.y - tolerance});
  const slam::CellIndex hi = costmap.cell_at({goal.x + tolerance, goal.y + tolerance});
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!costmap.contains({x, y})) continue;
      const std::size_t i = static_cast<std::size_t>(y - o.y) * static_cast<std::size_t>(costmap.width()) +
                            static_cast<std::size_t>(x - o.x);
      if (!reached[i]) continue;
      // Distance from the goal to the nearest point of this cell's square.
      const double nx = std::clamp(goal.x, x * res, (x + 1) * res);
      const double ny = std::clamp(goal.y, y * res, (y + 1) * res);
      if (std::hypot(goal.x - nx, goal.y - ny) <= tolerance) return true;
    }
  }
  return false;
}

}  // namespace lookahead::planner::detail
