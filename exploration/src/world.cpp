// SPDX-License-Identifier: MIT
#include "lookahead/exploration/world.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lookahead::exploration {

World::World(int width, int height, double resolution, const Eigen::Vector2d& origin, std::uint8_t fill)
    : width_(width), height_(height), resolution_(resolution), origin_(origin) {
  if (width <= 0 || height <= 0 || !(resolution > 0)) {
    throw std::invalid_argument("World: size and resolution must be positive (got " + std::to_string(width) + " x " +
                                std::to_string(height) + " at " + std::to_string(resolution) + " m)");
  }
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

slam::CellIndex World::cell_of(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d g = (p - origin_) / resolution_;
  return {static_cast<int>(std::floor(g.x())), static_cast<int>(std::floor(g.y()))};
}

Eigen::Vector2d World::center_of(slam::CellIndex c) const {
  return origin_ + resolution_ * Eigen::Vector2d(c.x + 0.5, c.y + 0.5);
}

void World::fill_rect(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, std::uint8_t value) {
  // First and one-past-last cell whose centre (i + 0.5) * res lies in [lo, hi).
  const auto first = [&](double v, double o) { return static_cast<int>(std::ceil((v - o) / resolution_ - 0.5)); };
  const int x0 = std::max(0, first(lo.x(), origin_.x()));
  const int y0 = std::max(0, first(lo.y(), origin_.y()));
  const int x1 = std::min(width_, first(hi.x(), origin_.x()));
  const int y1 = std::min(height_, first(hi.y(), origin_.y()));
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) set({x, y}, value);
  }
}

std::size_t World::free_cell_count() const {
  return static_cast<std::size_t>(std::count(cells_.begin(), cells_.end(), kFree));
}

double World::free_area_m2() const { return static_cast<double>(free_cell_count()) * resolution_ * resolution_; }

}  // namespace lookahead::exploration
