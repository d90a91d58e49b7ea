// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_attempts.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {

const PredictionAttempts::Attempt* PredictionAttempts::find(double x, double y) const {
  for (const Attempt& a : attempts_)
    if (std::hypot(a.x - x, a.y - y) <= options_.same_spot_radius) return &a;
  return nullptr;
}

std::size_t PredictionAttempts::known_cells(const slam::OccupancyGrid& map, double x, double y) const {
  // Sampled every 20 cm: a share of growth needs no finer count, and every frontier left is
  // checked at each idle moment.
  const slam::CellIndex c = map.cell_at(x, y);
  const int step = std::max(1, static_cast<int>(std::lround(0.2 / map.resolution())));
  const int r = static_cast<int>(std::ceil(options_.surroundings_diameter / 2 / map.resolution()));
  std::size_t known = 0;
  for (int dy = -r; dy <= r; dy += step)
    for (int dx = -r; dx <= r; dx += step)
      if (dx * dx + dy * dy <= r * r) known += map.is_known({c.x + dx, c.y + dy});
  return known;
}

void PredictionAttempts::add(const slam::OccupancyGrid& map, double x, double y, double now) {
  const Attempt a{x, y, now, options_.growth > 0 ? known_cells(map, x, y) : 0};
  if (const Attempt* old = find(x, y)) {
    attempts_[static_cast<std::size_t>(old - attempts_.data())] = a;
    return;
  }
  attempts_.push_back(a);
}

bool PredictionAttempts::tried_lately(const slam::OccupancyGrid& map, double x, double y, double now) const {
  const Attempt* a = find(x, y);
  if (!a) return false;
  if (now - a->time < options_.wait) return true;
  if (options_.growth <= 0) return false;
  return static_cast<double>(known_cells(map, x, y)) < (1.0 + options_.growth) * static_cast<double>(a->known_cells);
}

}  // namespace lookahead::exploration
