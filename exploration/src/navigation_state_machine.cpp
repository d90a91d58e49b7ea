// SPDX-License-Identifier: MIT
#include "lookahead/exploration/navigation_state_machine.hpp"

#include <stdexcept>
#include <string>

namespace lookahead::exploration {
namespace {

struct Transition {
  NavState from;
  NavEvent event;
  NavState to;
};

// The whole navigation on one screen (the table of navigation_state_machine.hpp).
constexpr Transition kTable[] = {
    {NavState::kLookAround, NavEvent::kLookedAround, NavState::kSelectTarget},
    {NavState::kSelectTarget, NavEvent::kPlanned, NavState::kFollow},
    {NavState::kSelectTarget, NavEvent::kSqueezed, NavState::kFollow},
    {NavState::kSelectTarget, NavEvent::kNoFrontier, NavState::kDone},
    {NavState::kSelectTarget, NavEvent::kWaitOnBlacklist, NavState::kLookAround},
    {NavState::kSelectTarget, NavEvent::kNoPath, NavState::kRecover},
    {NavState::kFollow, NavEvent::kGoalReached, NavState::kSelectTarget},
    {NavState::kFollow, NavEvent::kStuck, NavState::kSelectTarget},
    {NavState::kFollow, NavEvent::kGoalExplored, NavState::kSelectTarget},
    {NavState::kFollow, NavEvent::kGoalPredicted, NavState::kSelectTarget},
    {NavState::kFollow, NavEvent::kGoalDropped, NavState::kSelectTarget},
    {NavState::kFollow, NavEvent::kPathBlocked, NavState::kReplan},
    {NavState::kReplan, NavEvent::kReplanned, NavState::kFollow},
    {NavState::kReplan, NavEvent::kReplanFailed, NavState::kSelectTarget},
    {NavState::kReplan, NavEvent::kGoalDropped, NavState::kSelectTarget},
    {NavState::kRecover, NavEvent::kRecovered, NavState::kFollow},
    {NavState::kRecover, NavEvent::kLookAgain, NavState::kLookAround},
    {NavState::kRecover, NavEvent::kExhausted, NavState::kDone},
};

}  // namespace

const char* to_string(NavState s) {
  switch (s) {
    case NavState::kLookAround:
      return "look_around";
    case NavState::kSelectTarget:
      return "select_target";
    case NavState::kFollow:
      return "follow";
    case NavState::kReplan:
      return "replan";
    case NavState::kRecover:
      return "recover";
    case NavState::kDone:
      return "done";
  }
  return "unknown";
}

const char* to_string(NavEvent e) {
  switch (e) {
    case NavEvent::kNone:
      return "none";
    case NavEvent::kLookedAround:
      return "looked_around";
    case NavEvent::kPlanned:
      return "planned";
    case NavEvent::kSqueezed:
      return "squeezed";
    case NavEvent::kNoFrontier:
      return "no_frontier";
    case NavEvent::kWaitOnBlacklist:
      return "wait_on_blacklist";
    case NavEvent::kNoPath:
      return "no_path";
    case NavEvent::kGoalReached:
      return "goal_reached";
    case NavEvent::kStuck:
      return "stuck";
    case NavEvent::kGoalExplored:
      return "goal_explored";
    case NavEvent::kGoalPredicted:
      return "goal_predicted";
    case NavEvent::kGoalDropped:
      return "goal_dropped";
    case NavEvent::kPathBlocked:
      return "path_blocked";
    case NavEvent::kReplanned:
      return "replanned";
    case NavEvent::kReplanFailed:
      return "replan_failed";
    case NavEvent::kRecovered:
      return "recovered";
    case NavEvent::kLookAgain:
      return "look_again";
    case NavEvent::kExhausted:
      return "exhausted";
  }
  return "unknown";
}

NavState next_state(NavState state, NavEvent event) {
  if (event == NavEvent::kNone) return state;
  for (const Transition& t : kTable)
    if (t.from == state && t.event == event) return t.to;
  throw std::logic_error(std::string("navigation: no transition from ") + to_string(state) + " on " + to_string(event));
}

}  // namespace lookahead::exploration
