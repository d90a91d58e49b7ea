// SPDX-License-Identifier: MIT
#include "lookahead/predictor/unexplored_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lookahead::predictor {
namespace {

// The cells of a square window around f, each with its state in the fill.
class Window {
 public:
  Window(slam::CellIndex centre, int radius)
      : c_(centre), r_(radius), side_(2 * radius + 1), state_(static_cast<std::size_t>(side_) * side_, 0),
        near_wall_(state_.size(), 0) {}
  [[nodiscard]] bool within(slam::CellIndex c, int radius) const {
    const int dx = c.x - c_.x, dy = c.y - c_.y;
    return dx * dx + dy * dy <= radius * radius;
  }
  [[nodiscard]] bool inside(slam::CellIndex c) const { return std::abs(c.x - c_.x) <= r_ && std::abs(c.y - c_.y) <= r_; }
  std::uint8_t& state(slam::CellIndex c) { return state_[index(c)]; }
  std::uint8_t& near_wall(slam::CellIndex c) { return near_wall_[index(c)]; }

 private:
  [[nodiscard]] std::size_t index(slam::CellIndex c) const {
    return static_cast<std::size_t>((c.y - c_.y + r_) * side_ + (c.x - c_.x + r_));
  }
  slam::CellIndex c_;
  int r_, side_;
  std::vector<std::uint8_t> state_, near_wall_;
};

enum State : std::uint8_t { kNew = 0, kPassed = 1, kInRegion = 2 };

bool is_wall(const slam::OccupancyGrid& map, slam::CellIndex c) { return map.is_known(c) && map.raw_log_odds(c) > 0; }

std::array<slam::CellIndex, 4> neighbours(slam::CellIndex c) {
  return {slam::CellIndex{c.x + 1, c.y}, slam::CellIndex{c.x - 1, c.y}, slam::CellIndex{c.x, c.y + 1},
          slam::CellIndex{c.x, c.y - 1}};
}

// Marks the cells within `k` (square) of a mapped wall.
void mark_near_walls(const slam::OccupancyGrid& map, slam::CellIndex t, int r, int k, Window& w) {
  if (k <= 0) return;
  for (int y = t.y - r - k; y <= t.y + r + k; ++y) {
    for (int x = t.x - r - k; x <= t.x + r + k; ++x) {
      if (!is_wall(map, {x, y})) continue;
      for (int v = std::max(y - k, t.y - r); v <= std::min(y + k, t.y + r); ++v)
        for (int u = std::max(x - k, t.x - r); u <= std::min(x + k, t.x + r); ++u) w.near_wall({u, v}) = 1;
    }
  }
}

}  // namespace

std::vector<slam::CellIndex> unexplored_region(const slam::OccupancyGrid& map, double tx, double ty, double diameter,
                                               double min_opening) {
  const slam::CellIndex t = map.cell_at(tx, ty);
  const int r = static_cast<int>(std::ceil(diameter / 2 / map.resolution()));
  const int seed_r = std::min(r, static_cast<int>(std::ceil(kSeedRadius / map.resolution())));
  const int k = static_cast<int>(std::lround(min_opening / 2 / map.resolution()));
  Window w(t, r);
  mark_near_walls(map, t, r, k, w);
  // Seeds: the unknown cells within kSeedRadius that f reaches without crossing a wall
  // (4-connected through free and unknown cells; a mapped wall line is 8-connected, so it
  // stops the fill). The goal stands on free space near the frontier, not on it, hence the
  // radius. Until 2026-11-22 every unknown cell within the radius seeded the region.
  std::vector<slam::CellIndex> passed{t}, region;
  w.state(t) = kPassed;
  for (std::size_t i = 0; i < passed.size(); ++i) {
    for (const slam::CellIndex n : neighbours(passed[i])) {
      if (!w.within(n, seed_r) || w.state(n) != kNew) continue;
      if (!map.is_known(n)) {
        w.state(n) = kInRegion;
        region.push_back(n);
      } else if (!is_wall(map, n)) {
        w.state(n) = kPassed;
        passed.push_back(n);
      }
    }
  }
  // Breadth-first through unknown cells at least min_opening / 2 from every mapped wall,
  // so that a gap of a few cells in a wall (beams that missed it, typically where two walls
  // meet) does not let the region out: in the office study such gaps in the outer wall
  // made hypotheses of whole corridors outside the building.
  for (std::size_t i = 0; i < region.size(); ++i) {
    for (const slam::CellIndex n : neighbours(region[i])) {
      if (!w.within(n, r) || w.state(n) == kInRegion || map.is_known(n) || w.near_wall(n)) continue;
      w.state(n) = kInRegion;
      region.push_back(n);
    }
  }
  // ... then the unknown cells along the walls of what was reached: within k of a cell that
  // is at least k from every wall, so on its side of any wall.
  const std::size_t reached = region.size();
  for (std::size_t i = 0; i < reached; ++i) {
    const slam::CellIndex c = region[i];
    if (w.near_wall(c)) continue;
    for (int dy = -k; dy <= k; ++dy) {
      for (int dx = -k; dx <= k; ++dx) {
        const slam::CellIndex n{c.x + dx, c.y + dy};
        if (!w.within(n, r) || w.state(n) == kInRegion || map.is_known(n)) continue;
        w.state(n) = kInRegion;
        region.push_back(n);
      }
    }
  }
  return region;
}

}  // namespace lookahead::predictor
