// SPDX-License-Identifier: MIT
// Recovery behaviours: what the robot tries when a target selection found frontiers but
// planned no path to any (the Recover state, navigation_state_machine.hpp). Each behaviour
// says when it applies and runs on the mission through RecoveryActions; the mission tries
// them in a fixed order and takes the first that finds a way on. The default order:
//   backtrack      ordinary tries left, no frontier reachable: retrace the trail out of here
//   last_resort    ordinary tries used up: squeeze and backtrack, alternating (6 moves)
//   second_chance  ordinary tries used up, once per mission: goals blacklisted for good
//                  get their strikes back, and a shorter path left counts as progress
//   look_around    ordinary tries left: turn in place once more, then select again
// With none applying or succeeding the mission is trapped.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lookahead::exploration {

/// Why the mission is recovering.
struct RecoveryContext {
  /// The failed selection had frontiers with a goal, and no path reached any (not: every
  /// candidate's plan failed for another reason).
  bool unreachable = false;
  int failed_selections = 0;  ///< in a row, this one included
  int ordinary_tries = 3;     ///< failed selections in a row before the last resorts
  [[nodiscard]] bool tries_left() const { return failed_selections < ordinary_tries; }
};

enum class RecoveryOutcome {
  kFailed,         ///< no way on found: the next behaviour is tried
  kFollowing,      ///< a path to follow (a backtrack or a squeeze)
  kLookingAround,  ///< turn in place, then select again
  kStartOver,      ///< look around with the counts of tries started again (the second chance)
};

/// The moves recovery behaviours are made of (the mission implements them).
class RecoveryActions {
 public:
  /// Plans along the robot's own trail to the nearest crumb from which a frontier is
  /// reachable (or the trail's far end); true: the robot follows it.
  virtual bool backtrack() = 0;
  /// Plans to a frontier on the map inflated by the body alone (no safety margin); true:
  /// the robot follows it, closely tracked, guarded by the reactive stop.
  virtual bool squeeze() = 0;
  /// Gives the goals blacklisted for good their strikes back, and from then on a shorter
  /// path left counts as progress to the stuck clock; returns how many were forgiven.
  virtual std::size_t forgive_blacklist() = 0;
  /// Turns in place before the next selection.
  virtual void look_around() = 0;

 protected:
  ~RecoveryActions() = default;
};

class RecoveryBehaviour {
 public:
  virtual ~RecoveryBehaviour() = default;
  [[nodiscard]] virtual const char* name() const = 0;
  [[nodiscard]] virtual bool applies(const RecoveryContext& context) const = 0;
  virtual RecoveryOutcome run(RecoveryActions& actions) = 0;
  /// The robot got out of a trap (a target planned, a squeeze through): counts of tries
  /// start again.
  virtual void escaped() {}
};

enum class RecoveryKind { kBacktrack, kLastResort, kSecondChance, kLookAround };

/// Recovery names (named_choice.hpp style).
constexpr std::array<std::pair<RecoveryKind, const char*>, 4> choice_names(RecoveryKind) {
  return {{{RecoveryKind::kBacktrack, "backtrack"},
           {RecoveryKind::kLastResort, "last_resort"},
           {RecoveryKind::kSecondChance, "second_chance"},
           {RecoveryKind::kLookAround, "look_around"}}};
}

/// The order the mission tries its recovery behaviours in by default (mission.recovery_order).
inline std::vector<RecoveryKind> default_recovery_order() {
  return {RecoveryKind::kBacktrack, RecoveryKind::kLastResort, RecoveryKind::kSecondChance, RecoveryKind::kLookAround};
}

/// mission.recovery_order: comma-separated names (spaces around them ignored), each at most
/// once; "" is no behaviour. Throws std::invalid_argument naming the bad entry.
std::vector<RecoveryKind> parse_recovery_order(const std::string& text);

std::unique_ptr<RecoveryBehaviour> make_backtrack_recovery();
std::unique_ptr<RecoveryBehaviour> make_last_resort_recovery();
std::unique_ptr<RecoveryBehaviour> make_second_chance_recovery();
std::unique_ptr<RecoveryBehaviour> make_look_around_recovery();
std::unique_ptr<RecoveryBehaviour> make_recovery(RecoveryKind kind);
std::vector<std::unique_ptr<RecoveryBehaviour>> make_recoveries(const std::vector<RecoveryKind>& order);

/// Runs the behaviours in order; the first that applies and does not fail decides.
/// kFailed: none did (the mission is trapped).
RecoveryOutcome recover(const std::vector<std::unique_ptr<RecoveryBehaviour>>& behaviours,
                        const RecoveryContext& context, RecoveryActions& actions);

}  // namespace lookahead::exploration
