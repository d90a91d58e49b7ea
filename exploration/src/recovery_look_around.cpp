// SPDX-License-Identifier: MIT
// Look around: with ordinary tries left, no frontier may be reachable only for now (the map
// at the robot's back is thin after a long drive); a turn in place fills it in, and the next
// selection may find a way.
#include "lookahead/exploration/recovery_behaviour.hpp"

namespace lookahead::exploration {
namespace {

class LookAroundRecovery final : public RecoveryBehaviour {
 public:
  [[nodiscard]] const char* name() const override { return "look_around"; }
  [[nodiscard]] bool applies(const RecoveryContext& c) const override { return c.tries_left(); }
  RecoveryOutcome run(RecoveryActions& actions) override {
    actions.look_around();
    return RecoveryOutcome::kLookingAround;
  }
};

}  // namespace

std::unique_ptr<RecoveryBehaviour> make_look_around_recovery() { return std::make_unique<LookAroundRecovery>(); }

}  // namespace lookahead::exploration
