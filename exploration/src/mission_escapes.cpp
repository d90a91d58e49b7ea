// SPDX-License-Identifier: MIT
// The moves of the recovery behaviours (recovery_behaviour.hpp) when the costmap (body +
// safety margin) has no way on: a backtrack along the robot's own trail; a squeeze through
// a door the margin closes (planned on the map inflated by the body alone); and the second
// chance for the goals blacklisted for good.
#include <spdlog/spdlog.h>

#include <algorithm>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/target_selection.hpp"

namespace lookahead::exploration {
namespace {

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

std::size_t Mission::forgive_blacklist() {
  const std::size_t forgiven = blacklist_.forgive_permanent();
  if (forgiven == 0) return 0;
  stats_.forgiven_goals += static_cast<int>(forgiven);
  stuck_clock_.count_path_always();
  spdlog::debug("t {:.1f}: trapped by the blacklist: {} goal(s) get a second chance", time_, forgiven);
  return forgiven;
}

planner::Costmap Mission::body_costmap() const {
  planner::CostmapOptions body = options_.planner.costmap;
  body.robot_radius = options_.robot.radius;
  body.safety_margin = 0.0;
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
