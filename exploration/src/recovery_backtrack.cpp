// SPDX-License-Identifier: MIT
// Backtrack: with ordinary tries left and no frontier reachable, the robot retraces its own
// trail. The trail is where it has been, so the margin that closes the way on may still
// let it out the way it came; from a crumb further back a frontier is often reachable.
#include "lookahead/exploration/recovery_behaviour.hpp"

namespace lookahead::exploration {
namespace {

class BacktrackRecovery final : public RecoveryBehaviour {
 public:
  [[nodiscard]] const char* name() const override { return "backtrack"; }
  [[nodiscard]] bool applies(const RecoveryContext& c) const override { return c.unreachable && c.tries_left(); }
  RecoveryOutcome run(RecoveryActions& actions) override {
    return actions.backtrack() ? RecoveryOutcome::kFollowing : RecoveryOutcome::kFailed;
  }
};

}  // namespace

std::unique_ptr<RecoveryBehaviour> make_backtrack_recovery() { return std::make_unique<BacktrackRecovery>(); }

}  // namespace lookahead::exploration
