// SPDX-License-Identifier: MIT
#include "lookahead/exploration/recovery_behaviour.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "lookahead/slam/config/named_choice.hpp"

namespace lookahead::exploration {

namespace {

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

std::vector<RecoveryKind> parse_recovery_order(const std::string& text) {
  std::vector<RecoveryKind> order;
  if (trimmed(text).empty()) return order;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string name = trimmed(text.substr(start, comma == std::string::npos ? comma : comma - start));
    const std::optional<RecoveryKind> kind = slam::config::choice_from_name<RecoveryKind>(name);
    if (!kind) {
      throw std::invalid_argument("mission.recovery_order: unknown behaviour '" + name + "' in '" + text +
                                  "' (one of " + slam::config::choice_list<RecoveryKind>() + ")");
    }
    if (std::find(order.begin(), order.end(), *kind) != order.end())
      throw std::invalid_argument("mission.recovery_order: '" + name + "' twice in '" + text + "'");
    order.push_back(*kind);
    if (comma == std::string::npos) return order;
    start = comma + 1;
  }
}

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
