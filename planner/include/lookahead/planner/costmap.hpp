// SPDX-License-Identifier: MIT
// Binary traversability raster for a disc robot, built from an occupancy grid.
//
// A cell is blocked when its occupancy probability reaches `occupied_threshold`, or when it
// was never observed (unless `unknown_is_free`). Blocked cells are then inflated by the robot
// radius with an exact Euclidean distance transform (Felzenszwalb & Huttenlocher, "Distance
// Transforms of Sampled Functions", Theory of Computing 8, 2012): a cell is blocked when its
// centre lies within `robot_radius` of the centre of a blocked cell. After inflation the robot
// is a point: a centre position is collision-free exactly when its cell is free. This is the
// inscribed-radius convention of ROS costmaps. Distances run between cell centres, so a robot
// anywhere inside a free cell may come up to one cell diagonal (7 cm at 5 cm cells) closer
// to an occupied cell than `robot_radius`: give the radius that much slack when it matters.
//
// Part of the radius may be a safety margin (`safety_margin`): a cell then also knows whether
// the body alone, robot_radius - safety_margin, fits there. Planning keeps the margin; a path
// already planned stays valid while the body fits along it (path_fits_body), so a door the
// margin closes and opens again with every scan does not throw the path away at each refresh.
//
// The raster covers the grid's known bounds plus `margin`; everything outside it is blocked.
// Cells share the grid's indexing (same resolution and origin), so slam::CellIndex values of
// the grid address the costmap too. The costmap is a snapshot: rebuild it when the map
// changes, or update() it when the changes are known to lie in a window (the last scans).
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/planner/path.hpp"
#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::planner {

struct CostmapOptions {
  /// A known cell is an obstacle when its occupancy probability is >= this, (0.5, 1].
  double occupied_threshold = 0.65;
  /// Never-observed cells are traversable when true (optimistic planning into the unknown);
  /// by default they are obstacles.
  bool unknown_is_free = false;
  /// Inflation radius: the robot's circumscribed radius [m], [0, 5].
  double robot_radius = 0.25;
  /// Unknown border added around the known bounds [m], [0, 50]; useful with unknown_is_free.
  double margin = 0.5;
  /// The part of robot_radius that is safety margin, not body [m], [0, robot_radius].
  double safety_margin = 0.0;
};

/// Throws std::invalid_argument naming the field and value when an option is out of range.
void validate(const CostmapOptions& options);

class Costmap {
 public:
  /// An empty costmap: every query answers "blocked".
  Costmap() = default;
  /// Snapshot of `map` (validates `options`). Cost: O(cells) for the raster and inflation.
  Costmap(const slam::OccupancyGrid& map, const CostmapOptions& options);

  /// Brings the costmap up to date with `map`, whose cells changed only within [lo, hi]
  /// since the costmap was made from it: the same raster as a rebuild, at the cost of the
  /// window (a whole rebuild when the map's known bounds moved).
  void update(const slam::OccupancyGrid& map, slam::CellIndex lo, slam::CellIndex hi);

  [[nodiscard]] const CostmapOptions& options() const { return options_; }
  [[nodiscard]] double resolution() const { return resolution_; }
  [[nodiscard]] bool empty() const { return width_ == 0 || height_ == 0; }
  [[nodiscard]] int width() const { return width_; }    ///< cells along x
  [[nodiscard]] int height() const { return height_; }  ///< cells along y
  /// Cell of the raster's lower-left corner, in the grid's indexing.
  [[nodiscard]] slam::CellIndex origin() const { return origin_; }
  /// Metric extent of the raster: [min_corner, max_corner) [m].
  [[nodiscard]] Point2 min_corner() const;
  [[nodiscard]] Point2 max_corner() const;

  /// The cell containing a position (floor, like slam::OccupancyGrid::cell_at).
  [[nodiscard]] slam::CellIndex cell_at(Point2 p) const;
  [[nodiscard]] Point2 cell_center(slam::CellIndex c) const;
  [[nodiscard]] bool contains(slam::CellIndex c) const;

  /// Free after inflation; cells outside the raster are blocked.
  [[nodiscard]] bool cell_is_free(slam::CellIndex c) const;
  [[nodiscard]] bool is_free(double x, double y) const { return cell_is_free(cell_at({x, y})); }
  [[nodiscard]] bool is_free(Point2 p) const { return cell_is_free(cell_at(p)); }
  /// True when every cell the segment a-b passes through is free. Exact at cell resolution:
  /// a segment through a cell corner touches all four cells there, so it never slips
  /// diagonally between two blocked cells.
  [[nodiscard]] bool segment_is_free(Point2 a, Point2 b) const;
  /// Every segment of the path is free (a single waypoint: that cell is free).
  [[nodiscard]] bool path_is_free(const Path& path) const;

  /// The body (robot_radius - safety_margin) fits in the cell: free, or closed by the
  /// margin only. Cells outside the raster do not fit.
  [[nodiscard]] bool cell_fits_body(slam::CellIndex c) const;
  [[nodiscard]] bool fits_body(Point2 p) const { return cell_fits_body(cell_at(p)); }
  /// As path_is_free, for the body alone.
  [[nodiscard]] bool path_fits_body(const Path& path) const;

  [[nodiscard]] std::size_t free_cell_count() const;

 private:
  [[nodiscard]] std::size_t index(int local_x, int local_y) const {
    return static_cast<std::size_t>(local_y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(local_x);
  }
  /// Blocked cells reach this many cells (the radius, rounded up, plus one).
  [[nodiscard]] int inflation_reach() const;
  /// path_is_free / path_fits_body with the cell test `ok`.
  template <typename CellOk>
  [[nodiscard]] bool segment_passes(Point2 a, Point2 b, CellOk ok) const;
  /// Recomputes free_ over the raster rectangle [x0, x1] x [y0, y1] (local, inclusive).
  void inflate(const slam::OccupancyGrid& map, int x0, int y0, int x1, int y1);
  void mark_blocked_cells(const slam::OccupancyGrid& map, int x0, int y0, int w, int h,
                          std::vector<std::uint8_t>& blocked) const;

  CostmapOptions options_;
  double resolution_ = 0.05;
  slam::CellIndex origin_;
  slam::CellIndex known_lo_, known_hi_;  ///< the map's known bounds the raster was made for
  int width_ = 0;
  int height_ = 0;
  /// Per cell, row-major from origin_: kFree, kBodyFits (the margin closes it) or kBlocked.
  std::vector<std::uint8_t> free_;
  static constexpr std::uint8_t kBlocked = 0, kBodyFits = 1, kFree = 2;
};

}  // namespace lookahead::planner
