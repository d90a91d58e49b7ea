// SPDX-License-Identifier: MIT
// A test map of the P-SLAM paper's symmetric maze (3.5 m squares, 2.2 m corridors) as a
// laser would have mapped it up to x = explored_x: corridors known free, the squares'
// outlines occupied, their insides never seen. Everything beyond explored_x is unknown.
#pragma once

#include <cmath>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::predictor::test {

constexpr double kSquare = 3.5, kCorridor = 2.2, kPeriod = kSquare + kCorridor;

/// 0 in a corridor, 1 on a square's outline (within `wall` of its edge), 2 inside.
inline int maze_cell(double x, double y, double wall = 0.075) {
  const double u = std::fmod(x, kPeriod) - kCorridor, v = std::fmod(y, kPeriod) - kCorridor;
  if (u < 0 || v < 0) return 0;
  const double edge = std::min(std::min(u, kSquare - u), std::min(v, kSquare - v));
  return edge < wall ? 1 : 2;
}

inline slam::OccupancyGrid maze_grid(double explored_x, double size = 4 * kPeriod + kCorridor) {
  slam::OccupancyGrid g;
  const double res = g.resolution();
  for (double y = res / 2; y < size; y += res) {
    for (double x = res / 2; x < std::min(explored_x, size); x += res) {
      const int kind = maze_cell(x, y);
      if (kind == 0) g.add_log_odds(g.cell_at(x, y), -1000);
      if (kind == 1) g.add_log_odds(g.cell_at(x, y), 2000);
    }
  }
  return g;
}

}  // namespace lookahead::predictor::test
