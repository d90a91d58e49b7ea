// SPDX-License-Identifier: MIT
// The navigation of an exploration mission as a state machine: the states the robot's
// decision is in, the events each state's step reports, and the one transition table
// between them. Mission::decide() runs it once per laser period (mission_navigation.cpp):
// it steps the current state, moves along the table, and stops in a resting state
// (LookAround, Follow, Done), which waits for the next period. SelectTarget, Replan and
// Recover are passed through within one period.
//
//   state         event                           next state
//   LookAround    kLookedAround                   SelectTarget
//   SelectTarget  kPlanned, kSqueezed             Follow
//   SelectTarget  kNoFrontier                     Done (status done)
//   SelectTarget  kWaitOnBlacklist                LookAround
//   SelectTarget  kNoPath                         Recover
//   Follow        kGoalReached, kStuck,           SelectTarget
//                 kGoalExplored, kGoalPredicted,
//                 kGoalDropped
//   Follow        kPathBlocked                    Replan
//   Replan        kReplanned                      Follow
//   Replan        kReplanFailed, kGoalDropped     SelectTarget
//   Recover       kRecovered                      Follow
//   Recover       kLookAgain                      LookAround
//   Recover       kExhausted                      Done (status trapped)
//
// Any other pair is a programming error (std::logic_error).
#pragma once

namespace lookahead::exploration {

enum class NavState {
  kLookAround,    ///< turning in place to see around before (re)choosing a target
  kSelectTarget,  ///< choosing a frontier target and planning a path to it
  kFollow,        ///< driving the path to the current goal (pure pursuit)
  kReplan,        ///< the path is blocked: planning again to the same goal
  kRecover,       ///< no target could be planned: the recovery behaviours, in their order
  kDone,          ///< nothing is left to explore, or no recovery found a way on
};

enum class NavEvent {
  kNone,             ///< nothing happened: stay
  kLookedAround,     ///< the turn in place is complete
  kPlanned,          ///< a frontier target and a path to it
  kSqueezed,         ///< half through a door the margin closes: a path without the margin
  kNoFrontier,       ///< the map has no frontier left
  kWaitOnBlacklist,  ///< frontiers are left, all blacklisted for a while
  kNoPath,           ///< frontiers are left, none could be planned to
  kGoalReached,      ///< the follower reached the goal
  kStuck,            ///< no progress to the goal for stuck_time (stuck_clock.hpp)
  kGoalExplored,     ///< the goal's frontier is gone
  kGoalPredicted,    ///< look-ahead mapping covers the goal's frontier
  kGoalDropped,      ///< the goal is no longer worth a path
  kPathBlocked,      ///< new walls block the path, or the reactive stop held too long
  kReplanned,        ///< a new path to the same goal
  kReplanFailed,     ///< no path to the goal any more
  kRecovered,        ///< a recovery behaviour found a path (backtrack, squeeze)
  kLookAgain,        ///< a recovery behaviour chose to look around first
  kExhausted,        ///< no recovery behaviour applies or succeeds: trapped
};

const char* to_string(NavState state);
const char* to_string(NavEvent event);

/// The transition table: the state after `event` in `state`; kNone keeps the state.
/// Throws std::logic_error for an event the state cannot report.
NavState next_state(NavState state, NavEvent event);

/// A resting state waits for the next laser period; the others are passed through.
[[nodiscard]] constexpr bool resting(NavState state) {
  return state == NavState::kLookAround || state == NavState::kFollow || state == NavState::kDone;
}

}  // namespace lookahead::exploration
