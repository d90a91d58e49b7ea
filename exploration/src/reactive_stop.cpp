// SPDX-License-Identifier: MIT
#include "lookahead/exploration/reactive_stop.hpp"

#include "lookahead/exploration/swept_disc.hpp"

namespace lookahead::exploration {
namespace {

// Steps the reactive stop may hold the robot before its path is given up and replanned
// from where it stands (2 s at 10 Hz): the stop found something the path does not avoid.
constexpr int kStopsBeforeReplan = 20;

// Steps held before the robot tries to turn and creep out (1 s): a map that had not caught
// up with a wall refreshes within it; a hold that outlasts it is a corner pinning the body.
constexpr int kStopsBeforeEscape = kStopsBeforeReplan / 2;

// The reactive stop's corridor is this much wider than the body on each side [m].
constexpr double kStopSideClearance = 0.02;

}  // namespace

bool ReactiveStop::hold(bool must_wait) {
  // A stop that outlasts a costmap refresh is not a wall the map had not caught up with:
  // the robot is off its path, facing a door jamb it cut towards. Waiting for the stuck
  // clock (30 s) wastes the time; a new plan starts from the nearest free cell, away from it.
  // A backtrack or a squeeze has no other way to go: it waits, and the stuck clock gives it up.
  if (++held_ < kStopsBeforeReplan || must_wait) return false;
  held_ = 0;
  return true;
}

bool ReactiveStop::escape_due() const { return held_ == kStopsBeforeEscape; }

bool ReactiveStop::blocks(const slam::LaserScan& scan, const planner::VelocityCommand& cmd, const StopGeometry& g) {
  // Half through a door the margin closes (after a squeeze) the jambs are a few cm from the
  // body: what counts is whether the disc, driven along the commanded arc, runs into a
  // return (swept_disc.hpp). A straight corridor 2 cm wider than the body would catch the
  // jambs' noisy returns and hold the robot in the door, and would miss a jamb the arc
  // turns into.
  const double travel = cmd.v * g.period + g.stop_distance;
  if (g.tight) return disc_sweeps_into(scan, g.robot_radius, {cmd.v, cmd.omega, travel});
  // Elsewhere: the corridor the body sweeps in the next step plus the stop distance, in the
  // laser (= robot) frame, 2 cm wider than the body: end points inside it are walls about to
  // be hit.
  return corridor_holds_return(scan, g.robot_radius + kStopSideClearance, g.robot_radius + travel);
}

}  // namespace lookahead::exploration
