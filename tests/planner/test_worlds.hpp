// SPDX-License-Identifier: MIT
// Hand-made occupancy grids and brute-force oracles for the planner tests. The oracles share
// no code with the planner: inflation by scanning a disc of offsets, segments by clipping
// against each cell's square (Liang-Barsky), instead of the distance transform and the cell
// walk the library uses.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::planner::testing {

using slam::CellIndex;
using slam::OccupancyGrid;

/// Misses until the cell reads free (p <= 0.40), whatever it held before.
inline void set_free(OccupancyGrid& g, CellIndex c) {
  do {
    g.add_log_odds(c, g.fixed_miss());
  } while (g.raw_log_odds(c) > g.fixed_miss());
}
/// Three hits: p ~ 0.93 whatever the cell held before.
inline void set_occupied(OccupancyGrid& g, CellIndex c) {
  for (int i = 0; i < 3; ++i) g.add_log_odds(c, g.fixed_hit());
}
inline void fill(OccupancyGrid& g, int x0, int y0, int x1, int y1, bool occupied) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) occupied ? set_occupied(g, {x, y}) : set_free(g, {x, y});
  }
}

/// A 4 m x 3 m room (cells 0..79 x 0..59 at 5 cm) walled all round.
inline OccupancyGrid walled_room() {
  OccupancyGrid g;
  fill(g, 0, 0, 79, 59, false);
  fill(g, -1, -1, 80, -1, true);
  fill(g, -1, 60, 80, 60, true);
  fill(g, -1, -1, -1, 60, true);
  fill(g, 80, -1, 80, 60, true);
  return g;
}

/// The room split by a wall at x = 1.9..2.1 m with a gap at y = 2.0..2.8 m: from the lower
/// left to the lower right the only way is up through the gap.
inline OccupancyGrid corridor_with_gap(bool with_gap = true) {
  OccupancyGrid g = walled_room();
  fill(g, 38, 0, 41, 59, true);
  if (with_gap) fill(g, 38, 40, 41, 55, false);
  return g;
}

/// Inflated obstacle raster computed by brute force over the costmap's own extent.
struct Oracle {
  CellIndex origin;
  int width = 0;
  int height = 0;
  double resolution = 0.05;
  std::vector<std::uint8_t> blocked;

  [[nodiscard]] bool cell_blocked(int x, int y) const {
    const int lx = x - origin.x;
    const int ly = y - origin.y;
    if (lx < 0 || ly < 0 || lx >= width || ly >= height) return true;
    return blocked[static_cast<std::size_t>(ly * width + lx)] != 0;
  }

  /// Does segment a-b meet the (slightly shrunk) square of cell (x, y)? Liang-Barsky clip.
  [[nodiscard]] bool segment_meets_cell(Point2 a, Point2 b, int x, int y) const {
    const double eps = 1e-7 * resolution;
    const double lo[2] = {x * resolution + eps, y * resolution + eps};
    const double hi[2] = {(x + 1) * resolution - eps, (y + 1) * resolution - eps};
    const double p0[2] = {a.x, a.y};
    const double d[2] = {b.x - a.x, b.y - a.y};
    double t0 = 0.0, t1 = 1.0;
    for (int k = 0; k < 2; ++k) {
      if (d[k] == 0.0) {
        if (p0[k] < lo[k] || p0[k] > hi[k]) return false;
        continue;
      }
      double ta = (lo[k] - p0[k]) / d[k];
      double tb = (hi[k] - p0[k]) / d[k];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) return false;
    }
    return true;
  }

  [[nodiscard]] bool segment_free(Point2 a, Point2 b) const {
    const int x0 = static_cast<int>(std::floor(std::min(a.x, b.x) / resolution)) - 1;
    const int x1 = static_cast<int>(std::floor(std::max(a.x, b.x) / resolution)) + 1;
    const int y0 = static_cast<int>(std::floor(std::min(a.y, b.y) / resolution)) - 1;
    const int y1 = static_cast<int>(std::floor(std::max(a.y, b.y) / resolution)) + 1;
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (cell_blocked(x, y) && segment_meets_cell(a, b, x, y)) return false;
      }
    }
    return true;
  }

  [[nodiscard]] bool path_free(const Path& path) const {
    for (std::size_t i = 1; i < path.size(); ++i) {
      if (!segment_free(path[i - 1], path[i])) return false;
    }
    return !path.empty();
  }
};

/// Brute force: a cell is blocked if any raw-blocked cell of the extent has its centre
/// within `radius` of this cell's centre.
inline Oracle brute_force_costmap(const OccupancyGrid& g, const Costmap& extent, const CostmapOptions& o) {
  Oracle oracle{extent.origin(), extent.width(), extent.height(), g.resolution(), {}};
  const auto raw_blocked = [&](int x, int y) {
    if (x < oracle.origin.x || y < oracle.origin.y || x >= oracle.origin.x + oracle.width ||
        y >= oracle.origin.y + oracle.height) {
      return false;  // the costmap sees nothing outside its extent
    }
    if (!g.is_known({x, y})) return !o.unknown_is_free;
    return g.probability({x, y}) >= o.occupied_threshold;
  };
  const double r = o.robot_radius / g.resolution();
  const int reach = static_cast<int>(std::ceil(r));
  oracle.blocked.assign(static_cast<std::size_t>(oracle.width * oracle.height), 0);
  for (int ly = 0; ly < oracle.height; ++ly) {
    for (int lx = 0; lx < oracle.width; ++lx) {
      bool blocked = false;
      for (int dy = -reach; dy <= reach && !blocked; ++dy) {
        for (int dx = -reach; dx <= reach && !blocked; ++dx) {
          if (dx * dx + dy * dy > r * r + 1e-9) continue;
          blocked = raw_blocked(oracle.origin.x + lx + dx, oracle.origin.y + ly + dy);
        }
      }
      oracle.blocked[static_cast<std::size_t>(ly * oracle.width + lx)] = blocked ? 1 : 0;
    }
  }
  return oracle;
}

}  // namespace lookahead::planner::testing
