// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_aware_strategy.hpp"

#include <algorithm>

namespace lookahead::exploration {

std::string PredictionAwareStrategy::name() const {
  return base_->name() == "nearest" ? "predictive" : "predictive-" + base_->name();
}

std::optional<std::size_t> PredictionAwareStrategy::choose(const std::vector<Candidate>& c) const {
  std::vector<Candidate> open;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i].predicted_share >= skip_share_) continue;  // look-ahead mapping covers it
    open.push_back(c[i]);
    index.push_back(i);
  }
  const std::optional<std::size_t> pick = base_->choose(open);
  if (!pick) return std::nullopt;
  return index[*pick];
}

}  // namespace lookahead::exploration
