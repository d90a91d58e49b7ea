// SPDX-License-Identifier: MIT
// Log-odds occupancy grid with copy-on-write tiles and growing bounds, plus an incrementally
// maintained distance field (squared distance to the nearest obstacle, up to a radius) that
// the likelihood-field sensor model reads in O(1).
//
// Copying an OccupancyGrid copies tile handles only: particles share every tile until one
// of them writes to it, and then only that tile is duplicated. Copies may be written from
// different threads; one grid object must not be written from two threads at once.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/grid_options.hpp"
#include "lookahead/slam/grid/grid_tile.hpp"

namespace lookahead::slam {

class OccupancyGrid {
 public:
  explicit OccupancyGrid(const GridOptions& options = {});

  [[nodiscard]] const GridOptions& options() const { return options_; }
  [[nodiscard]] double resolution() const { return options_.resolution; }
  /// Field radius in cells; squared distances at or beyond its square read as far.
  [[nodiscard]] int distance_radius_cells() const { return radius_cells_; }

  // ---- reading (cheap; unknown space reads as kUnknown / far) ----
  [[nodiscard]] const GridTile* tile(int tx, int ty) const {
    const int ix = tx - tile_x0_;
    const int iy = ty - tile_y0_;
    if (ix < 0 || iy < 0 || ix >= tiles_w_ || iy >= tiles_h_) return nullptr;
    return tiles_[static_cast<std::size_t>(iy * tiles_w_ + ix)].get();
  }
  [[nodiscard]] std::int16_t raw_log_odds(CellIndex c) const {
    const GridTile* t = tile(c.x >> GridTile::kBits, c.y >> GridTile::kBits);
    return t ? t->log_odds[local(c)] : GridTile::kUnknown;
  }
  [[nodiscard]] int dist2(CellIndex c) const {
    const GridTile* t = tile(c.x >> GridTile::kBits, c.y >> GridTile::kBits);
    return t ? t->dist2[local(c)] : GridTile::kFar;
  }
  [[nodiscard]] bool is_known(CellIndex c) const { return raw_log_odds(c) != GridTile::kUnknown; }
  [[nodiscard]] bool is_obstacle(CellIndex c) const {
    const GridTile* t = tile(c.x >> GridTile::kBits, c.y >> GridTile::kBits);
    return t && (t->flags[local(c)] & GridTile::kObstacle);
  }
  /// Occupancy probability, 0.5 for unknown cells.
  [[nodiscard]] double probability(CellIndex c) const;

  // ---- geometry ----
  [[nodiscard]] CellIndex cell_at(double x, double y) const;
  /// Centre of a cell in metres.
  void cell_center(CellIndex c, double& x, double& y) const;
  /// Bounds of the cells ever written (inclusive); false when the grid is empty.
  bool known_bounds(CellIndex& min, CellIndex& max) const;

  // ---- writing ----
  /// Adds a fixed-point log-odds change to a cell (clamped), keeping the obstacle flag and
  /// the distance field consistent.
  void add_log_odds(CellIndex c, int delta) { add_log_odds_in(mutable_tile_of(c), c, delta); }
  /// Same, for a caller that already holds the cell's tile from mutable_tile().
  void add_log_odds_in(GridTile& t, CellIndex c, int delta);
  /// A tile this grid owns alone, created or duplicated as needed (the copy-on-write step).
  GridTile& mutable_tile(int tx, int ty);

  // ---- sharing statistics (memory studies, tests) ----
  [[nodiscard]] std::size_t tile_count() const;
  [[nodiscard]] std::size_t tiles_shared_with(const OccupancyGrid& other) const;

  static int local(CellIndex c) { return GridTile::index(c.x & (GridTile::kSide - 1), c.y & (GridTile::kSide - 1)); }

  /// Fixed-point values of the options, precomputed for the insertion loop.
  int fixed_hit() const { return hit_; }
  int fixed_miss() const { return miss_; }
  int fixed_min() const { return min_; }

 private:
  void grow_to_include(int tx, int ty);
  void on_became_obstacle(CellIndex c);
  void on_stopped_being_obstacle(CellIndex c);
  int nearest_obstacle_dist2(CellIndex c) const;
  GridTile& mutable_tile_of(CellIndex c) { return mutable_tile(c.x >> GridTile::kBits, c.y >> GridTile::kBits); }

  struct Offset {
    int dx, dy, d2;
  };

  GridOptions options_;
  int hit_, miss_, min_, max_, on_, off_;
  int radius_cells_;
  std::shared_ptr<const std::vector<Offset>> disk_;  // offsets within the radius, by distance
  /// Throws limits::ResourceLimitError when a tile table this size exceeds kMaxGridTiles.
  void check_extent(std::int64_t tiles_w, std::int64_t tiles_h) const;
  int tile_x0_ = 0, tile_y0_ = 0, tiles_w_ = 0, tiles_h_ = 0;
  std::vector<std::shared_ptr<GridTile>> tiles_;
};

}  // namespace lookahead::slam
