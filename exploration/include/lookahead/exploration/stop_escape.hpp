// SPDX-License-Identifier: MIT
// Turn, then creep: the way out of a corner the body touches. Pure pursuit aims along its
// path; when a wall corner sits a centimetre or two beside the body on that side, every
// forward step sweeps the disc into it, the reactive stop holds the robot, and the replans
// (and a backtrack to crumbs behind the corner) start from where it stands and aim the same
// way: the robot stays there until the time limit. The escape turns on the spot to the
// nearest heading along which the disc drives clear (swept_disc.hpp) and creeps a short way;
// the path's follower then takes over again from a spot the corner no longer pins.
#pragma once

#include "lookahead/planner/path_follower.hpp"
#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

/// The body and its limits during an escape.
struct EscapeLimits {
  double robot_radius = 0.25;  ///< [m]
  double max_speed = 0.5;      ///< [m/s]
  double max_turn_rate = 1.0;  ///< [rad/s]
  double period = 0.1;         ///< one control step [s]
};

class StopEscape {
 public:
  /// A new path: it gets one escape. Ends any escape under way.
  void arm();
  /// Starts an escape from `pose` when one is left for this path and a heading is clear on
  /// `scan`; false otherwise.
  bool start(const slam::LaserScan& scan, const slam::Pose2& pose, const EscapeLimits& limits);
  [[nodiscard]] bool active() const { return phase_ != Phase::kIdle; }
  /// This step's command; the escape ends when the creep has driven its distance or the
  /// swept disc would run into a return.
  planner::VelocityCommand command(const slam::LaserScan& scan, const slam::Pose2& pose, const EscapeLimits& limits);

 private:
  enum class Phase { kIdle, kTurn, kCreep };
  Phase phase_ = Phase::kIdle;
  bool armed_ = false;
  double heading_ = 0.0;  ///< world frame [rad]
  slam::Pose2 creep_start_;
};

}  // namespace lookahead::exploration
