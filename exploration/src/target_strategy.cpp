// SPDX-License-Identifier: MIT
#include "lookahead/exploration/target_strategy.hpp"

#include <stdexcept>

#include "lookahead/exploration/distance_advantage_strategy.hpp"
#include "lookahead/exploration/gain_rate_strategy.hpp"
#include "lookahead/exploration/prediction_aware_strategy.hpp"

namespace lookahead::exploration {

std::optional<std::size_t> NearestFrontierStrategy::choose(const std::vector<Candidate>& c) const {
  std::optional<std::size_t> best;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!best || c[i].path_cost < c[*best].path_cost) best = i;
  }
  return best;
}

std::optional<std::size_t> UtilityStrategy::choose(const std::vector<Candidate>& c) const {
  std::optional<std::size_t> best;
  double best_utility = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double u = c[i].information_gain - lambda_ * c[i].path_cost;
    if (!best || u > best_utility) {
      best = i;
      best_utility = u;
    }
  }
  return best;
}

std::unique_ptr<TargetStrategy> make_strategy(const std::string& name, double lambda, double skip_share,
                                              double rate_offset) {
  if (name == "nearest") return std::make_unique<NearestFrontierStrategy>();
  if (name == "utility") return std::make_unique<UtilityStrategy>(lambda);
  if (name == "predictive") {
    return std::make_unique<PredictionAwareStrategy>(std::make_unique<NearestFrontierStrategy>(), skip_share);
  }
  if (name == "predictive-utility") {
    return std::make_unique<PredictionAwareStrategy>(std::make_unique<UtilityStrategy>(lambda), skip_share);
  }
  if (name == "advantage") return std::make_unique<DistanceAdvantageStrategy>();
  if (name == "predictive-advantage") {
    return std::make_unique<PredictionAwareStrategy>(std::make_unique<DistanceAdvantageStrategy>(), skip_share);
  }
  if (name == "rate") return std::make_unique<GainRateStrategy>(rate_offset, false);
  if (name == "predictive-rate") return std::make_unique<GainRateStrategy>(rate_offset, true);
  throw std::invalid_argument("unknown strategy '" + name +
                              "' (nearest, utility, advantage, rate, predictive, predictive-utility, "
                              "predictive-advantage or predictive-rate)");
}

}  // namespace lookahead::exploration
