// SPDX-License-Identifier: MIT
#include "lookahead/exploration/information_gain.hpp"

#include <cmath>

namespace lookahead::exploration {

double information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                        const std::function<bool(slam::CellIndex)>& counts_as_known) {
  const double res = grid.resolution();
  // Sampled on a lattice of about 10 cm: the ranking does not need every 5 cm cell, and the
  // cost falls by the square of the step.
  const int step = std::max(1, static_cast<int>(std::lround(0.1 / res)));
  const slam::CellIndex centre = grid.cell_at(x, y);
  const int r = static_cast<int>(std::ceil(range / res));
  std::size_t unknown = 0;
  for (int dy = -r; dy <= r; dy += step) {
    for (int dx = -r; dx <= r; dx += step) {
      if (dx * dx + dy * dy > r * r) continue;
      const slam::CellIndex c{centre.x + dx, centre.y + dy};
      if (!grid.is_known(c) && !(counts_as_known && counts_as_known(c))) ++unknown;
    }
  }
  const double cell_area = (step * res) * (step * res);
  return static_cast<double>(unknown) * cell_area;
}

}  // namespace lookahead::exploration
