// SPDX-License-Identifier: MIT
// Ray-cast insertion of a laser scan into an occupancy grid (inverse sensor model).
#pragma once

#include <cmath>
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
  /// Trace each beam from the laser's true position to its true end point (trace_segment),
  /// not from cell centre to cell centre (trace_cells). A centre-to-centre line that grazes a
  /// wall dips into the wall's row up to 0.5 / slope cells before its end cell, so the far,
  /// grazing beams of a long corridor erase the wall the near beams mark, and a planner then
  /// goes through it. On in exploration missions; off in `slam`, whose published log
  /// figures it would change.
  bool exact_rays = false;
};

/// Inserts `scan` taken at robot pose `robot` into `grid`. Every cell a beam crosses gets
/// one miss, every cell a beam ends in gets one hit. Hits are marked before the misses are
/// cast, so a beam grazing a wall does not erase the endpoint of its neighbour in the same
/// scan (the two-phase update of OctoMap). No-returns are skipped unless
/// options.clear_no_returns says otherwise.
void insert_scan(OccupancyGrid& grid, const Pose2& robot, const LaserScan& scan, const InsertOptions& options);

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
  // A multiplication, not a shift: shifting a negative value left is undefined in C++17.
  std::int64_t minor =
      static_cast<std::int64_t>(x_major ? from.y : from.x) * (std::int64_t{1} << 32) + (std::int64_t{1} << 31);
  int major = x_major ? from.x : from.y;
  for (int k = 0; k <= n; ++k, major += major_step, minor += slope) {
    const int m = static_cast<int>(minor >> 32);
    if (!visit(x_major ? CellIndex{major, m} : CellIndex{m, major})) return;
  }
}

/// Calls visit(cell) for the cells of the segment between two points given in cell units
/// (cell (i, j) spans [i, i + 1) x [j, j + 1)), from the start's cell to the end's, one cell
/// per step along the major axis: at each inner column (row) the cell the segment crosses at
/// that column's centre line. Every cell visited is one the true segment passes through, so
/// a beam ending on a wall face never visits the wall's cells before its end cell. visit
/// returns false to stop.
template <typename Visit>
void trace_segment(double from_x, double from_y, double to_x, double to_y, Visit&& visit) {
  const bool x_major = std::abs(to_x - from_x) >= std::abs(to_y - from_y);
  const double f_major = x_major ? from_x : from_y, f_minor = x_major ? from_y : from_x;
  const double t_major = x_major ? to_x : to_y, t_minor = x_major ? to_y : to_x;
  const auto cell = [x_major](int major, int minor) {
    return x_major ? CellIndex{major, minor} : CellIndex{minor, major};
  };
  const int first = static_cast<int>(std::floor(f_major));
  const int last = static_cast<int>(std::floor(t_major));
  const CellIndex start = cell(first, static_cast<int>(std::floor(f_minor)));
  const CellIndex end = cell(last, static_cast<int>(std::floor(t_minor)));
  if (first == last) {  // under one column: the start's cell, then the end's if it differs
    if (visit(start) && !(end == start)) visit(end);
    return;
  }
  if (!visit(start)) return;
  const int step = last > first ? 1 : -1;
  const double slope = (t_minor - f_minor) / (t_major - f_major);
  // Inner columns at their centre line, the minor coordinate in 32.32 fixed point (as in
  // trace_cells: a step has no data-dependent branch).
  constexpr double kOne = 4294967296.0;
  std::int64_t minor = static_cast<std::int64_t>(std::floor((f_minor + (first + step + 0.5 - f_major) * slope) * kOne));
  const auto minor_step = static_cast<std::int64_t>(std::llround(step * slope * kOne));
  for (int major = first + step; major != last; major += step, minor += minor_step) {
    if (!visit(cell(major, static_cast<int>(minor >> 32)))) return;
  }
  visit(end);
}

}  // namespace lookahead::slam
