// SPDX-License-Identifier: MIT
// Visits every cell a straight segment passes through, in order: the voxel traversal of
// Amanatides & Woo, "A Fast Voxel Traversal Algorithm for Ray Tracing", Eurographics 1987.
// Deviation: where the segment passes (within 1e-9 cells) through a cell corner, both cells
// beside the corner are visited as well, so a path can never slip between two diagonal
// obstacles. Coordinates are in cell units (cell (i, j) spans [i, i+1) x [j, j+1)).
#pragma once

#include <cmath>
#include <cstdlib>
#include <limits>

namespace lookahead::planner::detail {

/// Calls visit(ix, iy, t) for each cell, t in [0, 1] being where along a->b the segment
/// enters it; stops early and returns false as soon as visit returns false.
template <typename Visit>
bool walk_segment(double ax, double ay, double bx, double by, Visit&& visit) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kCornerTolerance = 1e-9;
  int ix = static_cast<int>(std::floor(ax));
  int iy = static_cast<int>(std::floor(ay));
  const int ex = static_cast<int>(std::floor(bx));
  const int ey = static_cast<int>(std::floor(by));
  if (!visit(ix, iy, 0.0)) return false;
  const double dx = bx - ax;
  const double dy = by - ay;
  const int step_x = dx > 0 ? 1 : (dx < 0 ? -1 : 0);
  const int step_y = dy > 0 ? 1 : (dy < 0 ? -1 : 0);
  // Parameter t at which the segment crosses the next vertical / horizontal cell border.
  double t_max_x = step_x > 0 ? (ix + 1 - ax) / dx : (step_x < 0 ? (ix - ax) / dx : kInf);
  double t_max_y = step_y > 0 ? (iy + 1 - ay) / dy : (step_y < 0 ? (iy - ay) / dy : kInf);
  const double t_delta_x = step_x != 0 ? 1.0 / std::fabs(dx) : kInf;
  const double t_delta_y = step_y != 0 ? 1.0 / std::fabs(dy) : kInf;
  // Counting the borders left to cross, instead of comparing against the end cell, keeps the
  // walk finite whatever the rounding.
  int left_x = std::abs(ex - ix);
  int left_y = std::abs(ey - iy);
  while (left_x > 0 || left_y > 0) {
    const bool corner =
        left_x > 0 && left_y > 0 &&
        std::fabs(t_max_x - t_max_y) < kCornerTolerance * (t_delta_x < t_delta_y ? t_delta_x : t_delta_y);
    if (corner) {
      const double t = t_max_x < t_max_y ? t_max_x : t_max_y;
      if (!visit(ix + step_x, iy, t) || !visit(ix, iy + step_y, t)) return false;
      ix += step_x;
      iy += step_y;
      t_max_x += t_delta_x;
      t_max_y += t_delta_y;
      --left_x;
      --left_y;
      if (!visit(ix, iy, t)) return false;
      continue;
    }
    double t = 0.0;
    if (left_y == 0 || (left_x > 0 && t_max_x < t_max_y)) {
      t = t_max_x;
      ix += step_x;
      t_max_x += t_delta_x;
      --left_x;
    } else {
      t = t_max_y;
      iy += step_y;
      t_max_y += t_delta_y;
      --left_y;
    }
    if (!visit(ix, iy, t < 1.0 ? t : 1.0)) return false;
  }
  return true;
}

}  // namespace lookahead::planner::detail
