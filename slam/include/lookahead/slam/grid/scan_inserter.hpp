// SPDX-License-Identifier: MIT
// Ray-cast insertion of a laser scan into an occupancy grid (inverse sensor model).
#pragma once

#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam {

struct InsertOptions {
  /// Beams are used up to this range; longer readings clear free space up to it but mark
  /// no obstacle (far readings are too noisy in angle to place a wall) [m].
  double max_usable_range = 30.0;
};

/// Inserts `scan` taken at robot pose `robot` into `grid`. Every cell a beam crosses gets
/// one miss, every cell a beam ends in gets one hit. Hits are marked before the misses are
/// cast, so a beam grazing a wall does not erase the endpoint of its neighbour in the same
/// scan (the two-phase update of OctoMap). No-returns are skipped, as GMapping does: a
/// missing echo says nothing reliable about where free space ends.
void insert_scan(OccupancyGrid& grid, const Pose2& robot, const LaserScan& scan,
                 const InsertOptions& options);

/// Calls visit(cell) for every cell on the segment from `from` to `to`, both included
/// (Bresenham). visit returns false to stop early.
template <typename Visit>
void trace_cells(CellIndex from, CellIndex to, Visit&& visit) {
  const int dx = to.x > from.x ? to.x - from.x : from.x - to.x;
  const int dy = to.y > from.y ? to.y - from.y : from.y - to.y;
  const int sx = to.x > from.x ? 1 : -1;
  const int sy = to.y > from.y ? 1 : -1;
  int err = dx - dy;
  CellIndex c = from;
  for (;;) {
    if (!visit(c)) return;
    if (c == to) return;
    const int e2 = 2 * err;
    if (e2 > -dy) {
      err -= dy;
      c.x += sx;
    }
    if (e2 < dx) {
      err += dx;
      c.y += sy;
    }
  }
}

}  // namespace lookahead::slam
