// SPDX-License-Identifier: MIT
#include "lookahead/exploration/recovery_behaviour.hpp"

#include <spdlog/spdlog.h>

#include <stdexcept>

namespace lookahead::exploration {

std::unique_ptr<RecoveryBehaviour> make_recovery(RecoveryKind kind) {
  switch (kind) {
    case RecoveryKind::kBacktrack:
      return make_backtrack_recovery();
    case RecoveryKind::kLastResort:
      return make_last_resort_recovery();
    case RecoveryKind::kSecondChance:
      return make_second_chance_recovery();
    case RecoveryKind::kLookAround:
      return make_look_around_recovery();
  }
  throw std::invalid_argument("unknown recovery behaviour");
}

std::vector<std::unique_ptr<RecoveryBehaviour>> make_recoveries(const std::vector<RecoveryKind>& order) {
  std::vector<std::unique_ptr<RecoveryBehaviour>> behaviours;
  for (const RecoveryKind kind : order) behaviours.push_back(make_recovery(kind));
  return behaviours;
}

RecoveryOutcome recover(const std::vector<std::unique_ptr<RecoveryBehaviour>>& behaviours,
                        const RecoveryContext& context, RecoveryActions& actions) {
  for (const auto& b : behaviours) {
    if (!b->applies(context)) continue;
    const RecoveryOutcome outcome = b->run(actions);
    if (outcome == RecoveryOutcome::kFailed) continue;
    spdlog::debug("recovery: {} after {} failed selection(s)", b->name(), context.failed_selections);
    return outcome;
  }
  return RecoveryOutcome::kFailed;
}

}  // namespace lookahead::exploration
