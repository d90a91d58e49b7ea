// SPDX-License-Identifier: MIT
// The second chance: the third time the stuck clock gives a goal up, it is blacklisted for
// good. The clock measures progress as the straight line to the goal shrinking, and a long
// way round (a ring corridor, a hall entered from its far side) can lead away from the goal
// for longer than stuck_time, so the last frontiers of a building can be blacklisted for
// good while the robot was driving to them. Before calling a mission trapped, the goals
// blacklisted for good (by the stuck clock, or reached with their frontier left) get their
// strikes back once, and from then on a shorter path left counts as progress too. Only
// here: counting path progress from the start lets short replanned paths in doors the
// margin flickers on pass for progress (stuck_clock.hpp), so a mission that is never
// trapped keeps the stricter clock.
#include "lookahead/exploration/recovery_behaviour.hpp"

namespace lookahead::exploration {
namespace {

class SecondChanceRecovery final : public RecoveryBehaviour {
 public:
  [[nodiscard]] const char* name() const override { return "second_chance"; }
  [[nodiscard]] bool applies(const RecoveryContext& c) const override { return !c.tries_left(); }
  RecoveryOutcome run(RecoveryActions& actions) override {
    if (used_) return RecoveryOutcome::kFailed;
    used_ = true;
    if (actions.forgive_blacklist() == 0) return RecoveryOutcome::kFailed;
    actions.look_around();  // then choose among the forgiven goals
    return RecoveryOutcome::kStartOver;
  }

 private:
  bool used_ = false;  ///< once per mission
};

}  // namespace

std::unique_ptr<RecoveryBehaviour> make_second_chance_recovery() { return std::make_unique<SecondChanceRecovery>(); }

}  // namespace lookahead::exploration
