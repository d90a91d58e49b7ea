// SPDX-License-Identifier: MIT
// The last resort: the ordinary tries found no frontier the margin lets the robot reach.
// Before calling the mission trapped, a door wider than the body but narrower than body +
// margin is no wall: squeeze through it (a plan on the map inflated by the body alone). A
// squeeze the stuck clock gives up (a jamb the robot cannot pass) is followed by a
// backtrack, so the next squeeze starts elsewhere and aims at another frontier (the failed
// goal is blacklisted). It only runs once the ordinary tries are used up, so a mission that
// never runs out of them never squeezes.
#include "lookahead/exploration/recovery_behaviour.hpp"

namespace lookahead::exploration {
namespace {

// Moves (squeeze, backtrack, alternating) before the mission ends trapped. A squeeze that
// reaches its goal starts the count again.
constexpr int kLastResortTries = 6;

class LastResortRecovery final : public RecoveryBehaviour {
 public:
  [[nodiscard]] const char* name() const override { return "last_resort"; }
  [[nodiscard]] bool applies(const RecoveryContext& c) const override { return c.unreachable && !c.tries_left(); }
  RecoveryOutcome run(RecoveryActions& actions) override {
    if (moves_ >= kLastResortTries) return RecoveryOutcome::kFailed;
    ++moves_;
    const bool squeeze_first = moves_ % 2 == 1;
    const bool moved =
        squeeze_first ? (actions.squeeze() || actions.backtrack()) : (actions.backtrack() || actions.squeeze());
    return moved ? RecoveryOutcome::kFollowing : RecoveryOutcome::kFailed;
  }
  void escaped() override { moves_ = 0; }

 private:
  int moves_ = 0;  ///< squeezes and backtracks since the ordinary tries ran out
};

}  // namespace

std::unique_ptr<RecoveryBehaviour> make_last_resort_recovery() { return std::make_unique<LastResortRecovery>(); }

}  // namespace lookahead::exploration
