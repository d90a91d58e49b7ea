// SPDX-License-Identifier: MIT
#include "lookahead/exploration/predicted_map.hpp"

#include <cmath>

namespace lookahead::exploration {

void PredictedMap::add(const slam::HypothesisMap& h) {
  ++hypotheses_;
  slam::CellIndex lo, hi;
  if (!h.grid.known_bounds(lo, hi)) return;
  const auto psi = static_cast<float>(h.similarity);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const slam::CellIndex c{x, y};
      if (!h.grid.is_known(c) || confidence(c) > psi) continue;
      // Replace, not accumulate: the cell takes the better hypothesis' value.
      const int old = cells_.is_known(c) ? cells_.raw_log_odds(c) : 0;
      cells_.add_log_odds(c, h.grid.raw_log_odds(c) - old);
      confidence_[key(c)] = psi;
    }
  }
}

void PredictedMap::add(const slam::HypothesisMap& h, double target_x, double target_y) {
  add(h);
  targets_.push_back({target_x, target_y, h.similarity});
}

bool PredictedMap::target_predicted(double x, double y, double radius, double min_confidence) const {
  for (const Target& t : targets_)
    if (t.psi >= min_confidence && std::hypot(t.x - x, t.y - y) <= radius) return true;
  return false;
}

double PredictedMap::covered_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                   double min_confidence, bool by_target) const {
  // The frontier cluster's goal stands for the target cell f the predictor was given; the
  // goal of the same frontier moves a little as the map grows (1 m, as Mission's same goal).
  if (by_target && cluster.has_goal && target_predicted(cluster.goal_x, cluster.goal_y, 1.0, min_confidence))
    return 1.0;
  return predicted_share(map, cluster, min_confidence);
}

double PredictedMap::confidence(slam::CellIndex c) const {
  const auto it = confidence_.find(key(c));
  return it == confidence_.end() ? 0.0 : static_cast<double>(it->second);
}

double PredictedMap::predicted_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                     double min_confidence) const {
  std::size_t unknown = 0, covered = 0;
  for (const slam::CellIndex c : cluster.cells) {
    for (const slam::CellIndex n : {slam::CellIndex{c.x + 1, c.y}, slam::CellIndex{c.x - 1, c.y},
                                    slam::CellIndex{c.x, c.y + 1}, slam::CellIndex{c.x, c.y - 1}}) {
      if (map.is_known(n)) continue;
      ++unknown;
      covered += predicted(map, n) && confidence(n) >= min_confidence;
    }
  }
  return unknown > 0 ? static_cast<double>(covered) / static_cast<double>(unknown) : 0.0;
}

}  // namespace lookahead::exploration
