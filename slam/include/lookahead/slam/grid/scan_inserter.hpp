// SPDX-License-Identifier: MIT
// Ray-cast insertion of a laser scan into an occupancy grid (inverse sensor model).
#pragma once

#include <cstdint>
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
  /// Treat no-returns as free space up to the scan's max range. Off for real lasers (a
  /// missing echo may be glass or a dark surface, as GMapping assumes); on for simulated
  /// ones, whose no-return means exactly "nothing within range".
  bool clear_no_returns = false;
};

/// Inserts `scan` taken at robot pose `robot` into `grid`. Every cell a beam crosses gets
/// one miss, every cell a beam ends in gets one hit. Hits are marked before the misses are
/// cast, so a beam grazing a wall does not erase the endpoint of its neighbour in the same
/// scan (the two-phase update of OctoMap). No-returns are skipped unless
/// options.clear_no_returns says otherwise.
void insert_scan(OccupancyGrid& grid, const Pose2& robot, const LaserScan& scan,
                 const InsertOptions& options);

/// Calls visit(cell) for every cell on the segment from `from` to `to`, both included, one
/// cell per step along the major axis (the cells of Bresenham's line up to rounding ties).
/// The minor coordinate is carried in 32.32 fixed point, so a step has no data-dependent
/// branch: ray casting is the hottest loop of the filter. visit returns false to stop.
template <typename Visit>
void trace_cells(CellIndex from, CellIndex to, Visit&& visit) {
  const int dx = to.x - from.x;
  const int dy = to.y - from.y;
  const bool x_major = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const int n = x_major ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
  if (n == 0) {
    visit(from);
    return;
  }
  const int major_step = (x_major ? dx : dy) < 0 ? -1 : 1;
  const std::int64_t minor_delta = x_major ? dy : dx;
  const std::int64_t slope = (minor_delta * (std::int64_t{1} << 32)) / n;
  std::int64_t minor = (static_cast<std::int64_t>(x_major ? from.y : from.x) << 32) + (std::int64_t{1} << 31);
  int major = x_major ? from.x : from.y;
  for (int k = 0; k <= n; ++k, major += major_step, minor += slope) {
    const int m = static_cast<int>(minor >> 32);
    if (!visit(x_major ? CellIndex{major, m} : CellIndex{m, major})) return;
  }
}

}  // namespace lookahead::slam
