// SPDX-License-Identifier: MIT
// Which frontier to explore next: one interface, several strategies. P-SLAM's look-ahead
// mapping adds a prediction-aware strategy behind the same interface (predicted cells count as known in
// the information gain, confidently predicted frontiers may be skipped).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lookahead/exploration/frontier_detector.hpp"

namespace lookahead::exploration {

/// A frontier cluster priced for selection.
struct Candidate {
  const FrontierCluster* cluster = nullptr;
  double path_cost = 0.0;         ///< travel distance from the robot to the goal [m]
  double information_gain = 0.0;  ///< unknown area within sensor range of the goal [m^2]
  /// Share of the unknown cells beyond the frontier that confident hypotheses predict
  /// (priced only for strategies that use predictions).
  double predicted_share = 0.0;
};

/// How a strategy uses P-SLAM's look-ahead map (predicted_map.hpp).
enum class PredictionUse {
  kNone,
  /// Look-ahead mapping (P-SLAM sec. II-B): predicted cells count as known in the gain,
  /// predicted_share is filled in, and covered frontiers may be skipped.
  kSkip,
  /// The gain is seen through the prediction: predicted walls stop its rays, predicted
  /// free cells still count as unexplored (gain_rate_strategy.hpp).
  kOccludingGain,
};

class TargetStrategy {
 public:
  virtual ~TargetStrategy() = default;
  [[nodiscard]] virtual std::string name() const = 0;
  /// Index of the chosen candidate; nullopt when none is worth going to.
  [[nodiscard]] virtual std::optional<std::size_t> choose(const std::vector<Candidate>& candidates) const = 0;
  /// The choice with no candidate skipped, for when choose() skips them all: a predicted
  /// region counts as explored only once observed, so the robot still goes there.
  [[nodiscard]] virtual std::optional<std::size_t> choose_any(const std::vector<Candidate>& candidates) const {
    return choose(candidates);
  }
  /// How candidates are priced with the look-ahead map, if at all.
  [[nodiscard]] virtual PredictionUse prediction_use() const { return PredictionUse::kNone; }
  /// True when the mission must run the structure predictor for this strategy.
  [[nodiscard]] bool uses_prediction() const { return prediction_use() != PredictionUse::kNone; }
};

/// The closest frontier by path cost (Yamauchi 1997).
class NearestFrontierStrategy : public TargetStrategy {
 public:
  [[nodiscard]] std::string name() const override { return "nearest"; }
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>& c) const override;
};

/// Information gain minus weighted travel cost (Gonzalez-Banos & Latombe 2002):
/// utility = gain - lambda * cost.
class UtilityStrategy : public TargetStrategy {
 public:
  explicit UtilityStrategy(double lambda = 1.0) : lambda_(lambda) {}  ///< [m^2 per m]
  [[nodiscard]] std::string name() const override { return "utility"; }
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>& c) const override;

 private:
  double lambda_;
};

/// "nearest", "utility" (with `lambda`), "advantage" (distance_advantage_strategy.hpp),
/// "rate" (with `rate_offset`, gain_rate_strategy.hpp) or "predictive-rate" (its gain seen
/// through the prediction), or one of the first three with P-SLAM skipping
/// (prediction_aware_strategy.hpp): "predictive" (over nearest), "predictive-utility",
/// "predictive-advantage"; throws std::invalid_argument naming the choices otherwise.
std::unique_ptr<TargetStrategy> make_strategy(const std::string& name, double lambda = 1.0, double skip_share = 0.8,
                                              double rate_offset = 4.0);

}  // namespace lookahead::exploration
