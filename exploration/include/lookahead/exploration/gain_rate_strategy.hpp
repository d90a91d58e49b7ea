// SPDX-License-Identifier: MIT
// Gain rate: the frontier that reveals the most unknown area per metre of travel,
// gain / (cost + offset), first among the frontiers that would otherwise be left behind (the
// distance advantage, below). It is the rate form of the utility of Gonzalez-Banos & Latombe
// (2002): a greedy explorer that maximises area per metre reaches a coverage level sooner
// than one that trades area against metres at a fixed price. The offset stands for what
// every target costs besides its path (turning to it, the sensor's view from the goal) and
// keeps a sliver at arm's length, with other frontiers beside it, from outranking a room a
// few metres on.
//
// The metres are those of the trip and of the way back: every frontier is visited before the
// map is complete, so a target beyond the nearest frontier costs its path now and, later, the
// part of it beyond the nearest again to come back (cost + (cost - nearest cost)). Without
// it, a corridor's far end with a little more gain per metre than the rooms beside the robot
// wins, and the rooms wait for a crossing of the building at the end of the mission. When
// every frontier is far, the shared way cancels out.
//
// Frontiers the robot has the distance advantage on (Ericson et al. 2025: it is nearer to
// them, by path, than any other frontier is, in a straight line) come first, by rate among
// themselves; the rate ranks the rest only when there is none. No later target brings the
// robot back near such a frontier, so the rate's greed would leave it, a closet or a room's
// corner, for a dedicated trip at the end, when the last few per cent of the map cost the
// most. (Both rules' effect on time to 95 % explored: docs/results.md.)
//
// With prediction ("predictive-rate") the gain is seen through P-SLAM's look-ahead map
// (Chang et al. 2007, sec. II-B): predicted walls stop the gain's rays, predicted free cells
// still count as unexplored. A frontier into a small predicted room is worth its room, not
// the open disc the optimistic gain assumes; nothing is skipped, since a prediction is
// only explored once observed.
#pragma once

#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {

class GainRateStrategy : public TargetStrategy {
 public:
  /// `offset` [m] is added to every path cost; `predicted_gain` prices the gain through the
  /// look-ahead map.
  GainRateStrategy(double offset, bool predicted_gain) : offset_(offset), predicted_gain_(predicted_gain) {}
  [[nodiscard]] std::string name() const override { return predicted_gain_ ? "predictive-rate" : "rate"; }
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>& c) const override;
  [[nodiscard]] PredictionUse prediction_use() const override {
    return predicted_gain_ ? PredictionUse::kOccludingGain : PredictionUse::kNone;
  }

 private:
  double offset_;
  bool predicted_gain_;
};

/// Candidate `c`'s gain rate [m^2 per m]: information_gain / (2 path_cost - nearest_cost +
/// offset), where `nearest_cost` is the least path cost of all candidates.
[[nodiscard]] double gain_rate(const Candidate& c, double offset, double nearest_cost);

}  // namespace lookahead::exploration
