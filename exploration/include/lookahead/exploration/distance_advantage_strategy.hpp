// SPDX-License-Identifier: MIT
// Distance-advantage ordering of frontiers (after Ericson et al. 2025): a frontier the robot
// is nearer to than any other frontier is "its own": no later target brings the robot close
// to it again, so leaving it now costs a dedicated trip back. Among the frontiers where the
// robot has that advantage the nearest is chosen; when it has none, the nearest of all.
#pragma once

#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {

class DistanceAdvantageStrategy : public TargetStrategy {
 public:
  [[nodiscard]] std::string name() const override { return "advantage"; }
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>& c) const override;
};

/// The robot's advantage on candidate `i` [m]: the straight distance from its goal to the
/// nearest other candidate's goal, minus the robot's travel cost to it; +infinity when it
/// is the only candidate.
[[nodiscard]] double distance_advantage(const std::vector<Candidate>& c, std::size_t i);

}  // namespace lookahead::exploration
