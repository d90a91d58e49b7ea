// SPDX-License-Identifier: MIT
// The ways out when no frontier is reachable on the costmap: a backtrack along the robot's
// own trail, and, as the last resort before the mission is called trapped, a squeeze through
// a door the safety margin closes (planned on the map inflated by the body alone).
#include <spdlog/spdlog.h>

#include <algorithm>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/target_selection.hpp"

namespace lookahead::exploration {
namespace {

// Last-resort moves (squeeze, backtrack, alternating) before the mission ends trapped. A
// squeeze that reaches its goal starts the count again.
constexpr int kLastResortTries = 6;

// Tracking of a backtrack along the trail: look-ahead [m] and heading error that stops
// forward motion [rad].
constexpr double kBacktrackLookahead = 0.15;
constexpr double kBacktrackRotateAngle = 0.3;

}  // namespace

bool Mission::backtrack() {
  if (!options_.backtrack) return false;
  const Selection s = select_escape(selection_inputs(), crumbs_);
  if (s.outcome != SelectionOutcome::kPlanned) return false;
  ++stats_.backtracks;
  spdlog::debug("t {:.1f}: no frontier reachable: backtrack {} crumbs to ({:.2f}, {:.2f})", time_, s.path.size() - 1,
                s.goal_x, s.goal_y);
  backtracking_ = true;
  follow(s, close_tracking());
  return true;
}

bool Mission::last_resort() {
  // The ordinary tries found no frontier the margin lets the robot reach. Before calling it
  // trapped: a door wider than the body but narrower than body + margin is no wall. A
  // squeeze the stuck clock gives up (a jamb it cannot pass) is followed by a backtrack,
  // so the next squeeze starts elsewhere and aims at another frontier (the failed goal is
  // blacklisted). Only here, so a mission that never runs out of tries is unchanged.
  if (!options_.squeeze || last_resorts_ >= kLastResortTries) return false;
  ++last_resorts_;
  const bool squeeze_first = last_resorts_ % 2 == 1;
  return squeeze_first ? (squeeze() || backtrack()) : (backtrack() || squeeze());
}

bool Mission::squeeze() {
  if (!options_.squeeze) return false;
  planner::CostmapOptions body = options_.planner.costmap;
  body.robot_radius = options_.robot.radius;
  const planner::Costmap tight(map(), body);
  SelectionInputs in = selection_inputs();
  in.costmap = &tight;
  const Selection s = select_target(in);
  count(s);
  if (s.outcome != SelectionOutcome::kPlanned) return false;
  ++stats_.squeezes;
  spdlog::debug("t {:.1f}: no frontier reachable: squeeze to ({:.2f}, {:.2f}) without the margin", time_, s.goal_x,
                s.goal_y);
  // The margin would throw this path away at the next refresh; the reactive stop guards it.
  squeezing_ = true;
  tight_ = true;
  follow(s, close_tracking());
  return true;
}

planner::FollowerOptions Mission::close_tracking() const {
  // The path fits where it is drawn, not beside it: a door the margin closed may leave the
  // body a few cm, so it is tracked closely (a short look-ahead cuts less) and the robot
  // turns on the spot sooner rather than sweep a jamb into its stop.
  planner::FollowerOptions close = options_.follower;
  close.lookahead = std::min(close.lookahead, kBacktrackLookahead);
  close.rotate_in_place_angle = std::min(close.rotate_in_place_angle, kBacktrackRotateAngle);
  return close;
}

}  // namespace lookahead::exploration
