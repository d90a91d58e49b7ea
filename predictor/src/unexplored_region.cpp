// SPDX-License-Identifier: MIT
#include "lookahead/predictor/unexplored_region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace lookahead::predictor {

std::vector<slam::CellIndex> unexplored_region(const slam::OccupancyGrid& map, double tx, double ty, double diameter) {
  const slam::CellIndex t = map.cell_at(tx, ty);
  const int r = static_cast<int>(std::ceil(diameter / 2 / map.resolution()));
  const int seed_r = std::min(r, static_cast<int>(std::ceil(kSeedRadius / map.resolution())));
  const int side = 2 * r + 1;
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0);
  const auto within = [&](slam::CellIndex c, int radius) {
    const int dx = c.x - t.x, dy = c.y - t.y;
    return dx * dx + dy * dy <= radius * radius;
  };
  const auto mark = [&](slam::CellIndex c) -> std::uint8_t& {
    return seen[static_cast<std::size_t>((c.y - t.y + r) * side + (c.x - t.x + r))];
  };
  std::vector<slam::CellIndex> region;
  for (int dy = -seed_r; dy <= seed_r; ++dy) {
    for (int dx = -seed_r; dx <= seed_r; ++dx) {
      const slam::CellIndex c{t.x + dx, t.y + dy};
      if (!within(c, seed_r) || map.is_known(c) || mark(c)) continue;
      mark(c) = 1;
      region.push_back(c);
    }
  }
  for (std::size_t i = 0; i < region.size(); ++i) {  // breadth-first through unknown cells
    const slam::CellIndex c = region[i];
    for (const slam::CellIndex n : std::array<slam::CellIndex, 4>{
             slam::CellIndex{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}}) {
      if (!within(n, r) || mark(n) || map.is_known(n)) continue;
      mark(n) = 1;
      region.push_back(n);
    }
  }
  return region;
}

}  // namespace lookahead::predictor
