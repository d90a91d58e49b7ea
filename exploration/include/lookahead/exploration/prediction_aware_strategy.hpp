// SPDX-License-Identifier: MIT
// The P-SLAM exploration strategy (Chang et al. 2007, sec. II-B and V-A.1: "the robot can
// decide not to explore the predicted regions"): frontiers whose far side a confident
// hypothesis already predicts are skipped (look-ahead mapping instead of driving there),
// and the rest are ranked by a base strategy whose information gain counts predicted cells
// as known. Over "nearest" it isolates the effect of skipping; over "utility" the gains
// change too.
#pragma once

#include <memory>

#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {

class PredictionAwareStrategy : public TargetStrategy {
 public:
  /// Skips candidates with predicted_share >= skip_share, ranks the rest with `base`.
  PredictionAwareStrategy(std::unique_ptr<TargetStrategy> base, double skip_share)
      : base_(std::move(base)), skip_share_(skip_share) {}
  /// "predictive" over nearest, "predictive-utility" over utility.
  [[nodiscard]] std::string name() const override;
  /// nullopt when every candidate is predicted: nothing is left worth driving to.
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>& c) const override;
  /// The base strategy's choice over every candidate, predicted or not.
  [[nodiscard]] std::optional<std::size_t> choose_any(const std::vector<Candidate>& c) const override {
    return base_->choose(c);
  }
  [[nodiscard]] PredictionUse prediction_use() const override { return PredictionUse::kSkip; }

 private:
  std::unique_ptr<TargetStrategy> base_;
  double skip_share_;
};

}  // namespace lookahead::exploration
