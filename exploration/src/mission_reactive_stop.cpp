// SPDX-License-Identifier: MIT
// The reactive stop: no forward motion into laser returns the map has not caught up with,
// and a new path when the stop holds the robot for long.
#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/swept_disc.hpp"

namespace lookahead::exploration {
namespace {

// Steps the reactive stop may hold the robot before its path is given up and replanned
// from where it stands (2 s at 10 Hz): the stop found something the path does not avoid.
constexpr int kStopsBeforeReplan = 20;

// The reactive stop's corridor is this much wider than the body on each side [m].
constexpr double kStopSideClearance = 0.02;

}  // namespace

void Mission::hold_or_replan() {
  // A stop that outlasts a costmap refresh is not a wall the map had not caught up with:
  // the robot is off its path, facing a door jamb it cut towards. Waiting for the stuck
  // clock (30 s) wastes the time; a new plan starts from the nearest free cell, away from it.
  // A backtrack or a squeeze has no other way to go: it waits, and the stuck clock gives it up.
  if (++stop_streak_ < kStopsBeforeReplan || backtracking_ || squeezing_) return;
  stop_streak_ = 0;
  follower_.reset();
  path_blocked_ = true;
  ++stats_.replans;
}

bool Mission::path_ahead_blocked(const planner::VelocityCommand& cmd) const {
  // Half through a door the margin closes (after a squeeze) the jambs are a few cm from the
  // body: what counts is whether the disc, driven along the commanded arc, runs into a
  // return (swept_disc.hpp). A straight corridor 2 cm wider than the body would catch the
  // jambs' noisy returns and hold the robot in the door, and would miss a jamb the arc turns
  // into (kth_50010535_PLAN1, t = 1258 s, before this).
  const double travel = cmd.v * options_.laser.period() + options_.stop_distance;
  if (tight_) return disc_sweeps_into(last_scan_, options_.robot.radius, {cmd.v, cmd.omega, travel});
  // Elsewhere: the corridor the body sweeps in the next step plus the stop distance, in the
  // laser (= robot) frame, 2 cm wider than the body: end points inside it are walls about to
  // be hit.
  return corridor_holds_return(last_scan_, options_.robot.radius + kStopSideClearance, options_.robot.radius + travel);
}

}  // namespace lookahead::exploration
