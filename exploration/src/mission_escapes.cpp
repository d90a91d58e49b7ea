// SPDX-License-Identifier: MIT
// The ways out when the costmap (body + safety margin) has no way on: a backtrack along the
// robot's own trail; a squeeze through a door the margin closes (planned on the map inflated
// by the body alone) when the margin closes the way to the current goal, and as the last
// resort before the mission is called trapped; and, before that call, a second chance for
// the goals blacklisted for good.
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
  if (last_resorts_ >= kLastResortTries) return false;
  ++last_resorts_;
  const bool squeeze_first = last_resorts_ % 2 == 1;
  return squeeze_first ? (squeeze() || backtrack()) : (backtrack() || squeeze());
}

bool Mission::second_chance() {
  // The third time the stuck clock gives a goal up, it is blacklisted for good. The clock
  // measures progress as the straight line to the goal shrinking, and a long way round
  // (a ring corridor, a hall entered from its far side) can lead away from the goal for
  // more than stuck_time: on kth_50010540 (seed 3, utility) the last two frontiers were
  // given up three times each while the robot was driving to them, and the mission ended
  // trapped at 33 % coverage. Before calling a mission trapped, the goals blacklisted for
  // good (by the stuck clock, or reached with their frontier left) get their strikes back
  // once, and from then on a shorter path left counts as progress too. Only
  // here, so a mission that is never trapped is unchanged (progress along the path from
  // the start makes nearest worse on kth_50015848: 79 % against 91.5 % at the 4 h guard).
  if (second_chance_used_) return false;
  second_chance_used_ = true;
  const std::size_t forgiven = blacklist_.forgive_permanent();
  if (forgiven == 0) return false;
  stats_.forgiven_goals += static_cast<int>(forgiven);
  stuck_clock_.count_path_always();
  unreachable_streak_ = 0;
  last_resorts_ = 0;
  spdlog::debug("t {:.1f}: trapped by the blacklist: {} goal(s) get a second chance", time_, forgiven);
  turned_ = 0.0;  // look around, then choose among the forgiven goals
  return true;
}

planner::Costmap Mission::body_costmap() const {
  planner::CostmapOptions body = options_.planner.costmap;
  body.robot_radius = options_.robot.radius;
  return planner::Costmap(map(), body);
}

bool Mission::squeeze() {
  const planner::Costmap tight = body_costmap();
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
