// SPDX-License-Identifier: MIT
#include "lookahead/exploration/information_gain.hpp"

#include <algorithm>
#include <cmath>

#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::exploration {
namespace {

bool unknown(const slam::OccupancyGrid& grid, slam::CellIndex c, const CountsAsKnown& counts_as_known) {
  return !grid.is_known(c) && !(counts_as_known && counts_as_known(c));
}

}  // namespace

double visible_information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                                const CountsAsKnown& counts_as_known, const Occludes& occludes) {
  const double res = grid.resolution();
  // Rays about 0.2 m apart at the full range: a ranking needs no finer fan, and the cost is
  // that of the disc's 10 cm lattice (each ray stops at the first wall).
  const int rays = std::max(64, static_cast<int>(std::ceil(2 * M_PI * range / 0.2)));
  const double dtheta = 2 * M_PI / rays;
  const double gx = x / res, gy = y / res;  // in cell units, as trace_segment wants them
  double area = 0.0;
  for (int k = 0; k < rays; ++k) {
    const double c = std::cos(k * dtheta), s = std::sin(k * dtheta);
    // trace_segment visits one cell per step along the ray's major axis, each step this long;
    // the i-th visited cell stands for the polar strip between r = i * step and (i + 1) * step
    // (cut at the range), dtheta (r1^2 - r0^2) / 2, so a ray through unknown space alone adds
    // dtheta * range^2 / 2 and an empty map sums to pi range^2.
    const double step = res / std::max(std::abs(c), std::abs(s));
    int i = 0;
    double ray_area = 0.0;
    slam::trace_segment(gx, gy, gx + c * range / res, gy + s * range / res, [&](slam::CellIndex cell) {
      if (grid.is_obstacle(cell) || (occludes && occludes(cell))) return false;  // occluded from here on
      const double r0 = std::min(i * step, range), r1 = std::min((i + 1) * step, range);
      if (unknown(grid, cell, counts_as_known)) ray_area += 0.5 * (r1 * r1 - r0 * r0);
      ++i;
      return true;
    });
    area += ray_area * dtheta;
  }
  return area;
}

double information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                        const CountsAsKnown& counts_as_known) {
  const double res = grid.resolution();
  // Sampled on a lattice of about 10 cm: the ranking does not need every 5 cm cell, and the
  // cost falls by the square of the step.
  const int step = std::max(1, static_cast<int>(std::lround(0.1 / res)));
  const slam::CellIndex centre = grid.cell_at(x, y);
  const int r = static_cast<int>(std::ceil(range / res));
  std::size_t count = 0;
  for (int dy = -r; dy <= r; dy += step) {
    for (int dx = -r; dx <= r; dx += step) {
      if (dx * dx + dy * dy > r * r) continue;
      if (unknown(grid, {centre.x + dx, centre.y + dy}, counts_as_known)) ++count;
    }
  }
  const double cell_area = (step * res) * (step * res);
  return static_cast<double>(count) * cell_area;
}

}  // namespace lookahead::exploration
