// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_aware_strategy.hpp"

#include <algorithm>

namespace lookahead::exploration {

std::string PredictionAwareStrategy::name() const {
  return base_->name() == "nearest" ? "predictive" : "predictive-" + base_->name();
}

std::optional<std::size_t> PredictionAwareStrategy::choose(const std::vector<Candidate>& c) const {
  // Frontiers bordering a predicted region come last: as the map around them grows, the
  // rest of their region may be predicted too, and then they need no visit at all.
  const bool clear_ones = std::any_of(c.begin(), c.end(), [&](const Candidate& x) {
    return x.predicted_share < skip_share_ && !x.borders_prediction;
  });
  std::vector<Candidate> open;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i].predicted_share >= skip_share_) continue;  // look-ahead mapping covers it
    if (clear_ones && c[i].borders_prediction) continue;
    open.push_back(c[i]);
    index.push_back(i);
  }
  const std::optional<std::size_t> pick = base_->choose(open);
  if (!pick) return std::nullopt;
  return index[*pick];
}

}  // namespace lookahead::exploration
