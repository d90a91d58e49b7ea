// SPDX-License-Identifier: MIT
#include "lookahead/exploration/gain_rate_strategy.hpp"

#include <algorithm>
#include <limits>

#include "lookahead/exploration/distance_advantage_strategy.hpp"

namespace lookahead::exploration {

double gain_rate(const Candidate& c, double offset, double nearest_cost) {
  return c.information_gain / (2.0 * c.path_cost - nearest_cost + offset);
}

std::optional<std::size_t> GainRateStrategy::choose(const std::vector<Candidate>& c) const {
  double nearest_cost = std::numeric_limits<double>::infinity();
  for (const Candidate& candidate : c) nearest_cost = std::min(nearest_cost, candidate.path_cost);
  struct Rank {
    bool own;     // the robot has the distance advantage on it (gain_rate_strategy.hpp)
    double rate;  // gain per metre of the trip and the way back
    double cost;  // ties (no gain anywhere) go to the nearer frontier
  };
  const auto rank = [&](std::size_t i) {
    return Rank{distance_advantage(c, i) > 0.0, gain_rate(c[i], offset_, nearest_cost), c[i].path_cost};
  };
  const auto before = [](const Rank& a, const Rank& b) {
    if (a.own != b.own) return a.own;
    if (a.rate != b.rate) return a.rate > b.rate;
    return a.cost < b.cost;
  };
  std::optional<std::size_t> best;
  Rank best_rank{};
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Rank r = rank(i);
    if (!best || before(r, best_rank)) {
      best = i;
      best_rank = r;
    }
  }
  return best;
}

}  // namespace lookahead::exploration
