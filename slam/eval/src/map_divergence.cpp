// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/map_divergence.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam {

MapDivergence map_divergence(const ProbabilityMap& reference, const ProbabilityMap& map) {
  MapDivergence d;
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      const double p_raw = reference.at(x, y);
      if (p_raw < 0) continue;
      // The same point in the other map's raster (origins may differ by whole cells).
      const double wx = reference.origin_x + (x + 0.5) * reference.resolution;
      const double wy = reference.origin_y + (y + 0.5) * reference.resolution;
      const int mx = static_cast<int>(std::floor((wx - map.origin_x) / map.resolution));
      const int my = static_cast<int>(std::floor((wy - map.origin_y) / map.resolution));
      if (mx < 0 || my < 0 || mx >= map.width || my >= map.height || map.at(mx, my) < 0) continue;
      const double p = std::clamp(p_raw, 0.001, 0.999), q = std::clamp(map.at(mx, my), 0.001, 0.999);
      d.total += p * std::log(p / q) + (1 - p) * std::log((1 - p) / (1 - q));
      ++d.compared;
    }
  }
  return d;
}

}  // namespace lookahead::slam
