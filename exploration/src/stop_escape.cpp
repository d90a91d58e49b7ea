// SPDX-License-Identifier: MIT
#include "lookahead/exploration/stop_escape.hpp"

#include <algorithm>
#include <cmath>

#include "lookahead/exploration/swept_disc.hpp"

namespace lookahead::exploration {
namespace {

// The creep [m]: two body radii of the KTH setups take the body's edge clear of the corner
// it touched, and stay short of walls a laser period's map update has not caught.
constexpr double kCreepDistance = 0.2;

// The creep runs at this share of the top speed: it passes walls a centimetre away.
constexpr double kCreepSpeedShare = 0.5;

// The turn is done within this heading error [rad]: over the creep a degree off the
// heading moves the body 3 mm sideways. The turn rate is this gain times the error, up to
// the limit [1/s]; the creep holds its heading with the same gain.
constexpr double kTurnTolerance = 0.02;
constexpr double kTurnGain = 2.0;

// The heading is chosen with this much room beside the body [m]: the creep, guarded by the
// body alone, keeps a centimetre for the heading it cannot hold exactly.
constexpr double kChoiceClearance = 0.01;

// Each creep step checks the disc this far beyond the step's travel [m].
constexpr double kCreepLookahead = 0.05;

double heading_error(double target, double heading) { return std::remainder(target - heading, 2.0 * M_PI); }

}  // namespace

void StopEscape::arm() {
  armed_ = true;
  phase_ = Phase::kIdle;
}

bool StopEscape::start(const slam::LaserScan& scan, const slam::Pose2& pose, const EscapeLimits& limits) {
  if (!armed_) return false;
  // Nearest to where the robot faces: it had turned towards its path before the stop held it.
  const auto heading =
      clear_heading(scan, limits.robot_radius + kChoiceClearance, kCreepDistance + kCreepLookahead, 0.0);
  if (!heading) return false;
  armed_ = false;
  heading_ = pose.theta + *heading;
  phase_ = Phase::kTurn;
  return true;
}

planner::VelocityCommand StopEscape::command(const slam::LaserScan& scan, const slam::Pose2& pose,
                                             const EscapeLimits& limits) {
  planner::VelocityCommand cmd;
  const double error = heading_error(heading_, pose.theta);
  cmd.omega = std::clamp(kTurnGain * error, -limits.max_turn_rate, limits.max_turn_rate);
  if (phase_ == Phase::kTurn) {
    if (std::abs(error) > kTurnTolerance) return cmd;
    phase_ = Phase::kCreep;
    creep_start_ = pose;
  }
  const double driven = std::hypot(pose.x - creep_start_.x, pose.y - creep_start_.y);
  const double v = kCreepSpeedShare * limits.max_speed;
  const DiscMotion step{v, 0.0, v * limits.period + kCreepLookahead};
  if (driven >= kCreepDistance || disc_sweeps_into(scan, limits.robot_radius, step)) {
    phase_ = Phase::kIdle;
    return {};
  }
  cmd.v = v;
  return cmd;
}

}  // namespace lookahead::exploration
