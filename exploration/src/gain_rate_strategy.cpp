// SPDX-License-Identifier: MIT
#include "lookahead/exploration/gain_rate_strategy.hpp"

#include <algorithm>
#include <limits>

namespace lookahead::exploration {

double gain_rate(const Candidate& c, double offset, double nearest_cost) {
  return c.information_gain / (2.0 * c.path_cost - nearest_cost + offset);
}

std::optional<std::size_t> GainRateStrategy::choose(const std::vector<Candidate>& c) const {
  double nearest_cost = std::numeric_limits<double>::infinity();
  for (const Candidate& candidate : c) nearest_cost = std::min(nearest_cost, candidate.path_cost);
  std::optional<std::size_t> best;
  double best_rate = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double rate = gain_rate(c[i], offset_, nearest_cost);
    // Ties (no gain anywhere, as when every frontier's surroundings are seen) go to the
    // nearer frontier.
    const bool better = !best || rate > best_rate || (rate == best_rate && c[i].path_cost < c[*best].path_cost);
    if (better) {
      best = i;
      best_rate = rate;
    }
  }
  return best;
}

}  // namespace lookahead::exploration
