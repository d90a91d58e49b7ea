// SPDX-License-Identifier: MIT
#include "lookahead/exploration/distance_advantage_strategy.hpp"

#include <cmath>
#include <limits>

namespace lookahead::exploration {

double distance_advantage(const std::vector<Candidate>& c, std::size_t i) {
  double nearest_other = std::numeric_limits<double>::infinity();
  const FrontierCluster& f = *c[i].cluster;
  for (std::size_t j = 0; j < c.size(); ++j) {
    if (j == i) continue;
    nearest_other =
        std::min(nearest_other, std::hypot(c[j].cluster->goal_x - f.goal_x, c[j].cluster->goal_y - f.goal_y));
  }
  return nearest_other - c[i].path_cost;
}

std::optional<std::size_t> DistanceAdvantageStrategy::choose(const std::vector<Candidate>& c) const {
  std::optional<std::size_t> best;
  bool best_has_advantage = false;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const bool advantage = distance_advantage(c, i) > 0;
    const bool better = !best || (advantage && !best_has_advantage) ||
                        (advantage == best_has_advantage && c[i].path_cost < c[*best].path_cost);
    if (better) {
      best = i;
      best_has_advantage = advantage;
    }
  }
  return best;
}

}  // namespace lookahead::exploration
