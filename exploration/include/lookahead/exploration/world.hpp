// SPDX-License-Identifier: MIT
// The ground-truth world the simulator drives in: a binary occupancy raster. Same layout as
// slam/io/map_io.hpp's ProbabilityMap (row 0 = bottom, y up, origin = lower-left corner of
// cell (0, 0)), but one byte per cell and no "unknown": the truth is either free or not.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "lookahead/slam/grid/cell_index.hpp"

namespace lookahead::exploration {

class World {
 public:
  static constexpr std::uint8_t kFree = 0;
  static constexpr std::uint8_t kOccupied = 1;

  World() = default;
  /// width x height cells of `resolution` metres, all set to `fill`; throws
  /// std::invalid_argument on a non-positive size or resolution.
  World(int width, int height, double resolution, const Eigen::Vector2d& origin, std::uint8_t fill = kFree);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double resolution() const { return resolution_; }          ///< [m/cell]
  [[nodiscard]] const Eigen::Vector2d& origin() const { return origin_; }  ///< [m]
  [[nodiscard]] double width_m() const { return width_ * resolution_; }
  [[nodiscard]] double height_m() const { return height_ * resolution_; }

  [[nodiscard]] bool contains(slam::CellIndex c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  /// The cell whose square holds p (floor, so it may lie outside the raster).
  [[nodiscard]] slam::CellIndex cell_of(const Eigen::Vector2d& p) const;
  [[nodiscard]] Eigen::Vector2d center_of(slam::CellIndex c) const;

  /// Outside the raster counts as occupied: a robot cannot leave the building.
  [[nodiscard]] bool is_occupied(slam::CellIndex c) const { return !contains(c) || cells_[index(c)] != kFree; }
  [[nodiscard]] bool is_occupied(double x, double y) const { return is_occupied(cell_of({x, y})); }

  void set(slam::CellIndex c, std::uint8_t value) { cells_[index(c)] = value; }
  /// Sets every cell whose centre lies in [lo, hi) (metres); cells outside are ignored.
  void fill_rect(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, std::uint8_t value);

  [[nodiscard]] const std::vector<std::uint8_t>& cells() const { return cells_; }
  [[nodiscard]] std::size_t free_cell_count() const;
  [[nodiscard]] double free_area_m2() const;

  /// Where the world came from (file, resolved bitmap, generator and seed), for run records.
  [[nodiscard]] const std::string& source() const { return source_; }
  void set_source(std::string source) { source_ = std::move(source); }

 private:
  [[nodiscard]] std::size_t index(slam::CellIndex c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c.x);
  }

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.05;
  Eigen::Vector2d origin_{0.0, 0.0};
  std::vector<std::uint8_t> cells_;
  std::string source_;
};

}  // namespace lookahead::exploration
