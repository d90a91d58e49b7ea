// SPDX-License-Identifier: MIT
// A Pioneer 3-DX-like differential-drive robot as a unicycle disc: commands (v, omega) are
// clamped to the limits and integrated exactly along the arc they describe; the disc stops
// at the last collision-free point before a wall.
#pragma once

#include <Eigen/Core>

#include "lookahead/exploration/world.hpp"
#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::exploration {

struct RobotOptions {
  /// Disc radius [m], > 0. The P3-DX body is about 0.45 m x 0.38 m; 0.25 m encloses most of it.
  double radius = 0.25;
  /// [m/s], > 0. P-SLAM's Stage runs drove the P3-DX at "a top speed of 0.2 m/s" (Sec. IV-A),
  /// so exploration times compare with its 684 s / 457 s.
  double max_speed = 0.2;
  /// [rad/s], > 0. P-SLAM gives none; our choice, well within what a P3-DX turns.
  double max_turn_rate = 1.0;
  /// Longest straight piece between collision checks along an arc [m], > 0; below the
  /// 5 cm cells so the disc cannot jump a wall.
  double collision_step = 0.02;

  void validate() const;  ///< throws std::invalid_argument naming the field and value
};

struct StepResult {
  slam::Pose2 pose;       ///< true pose after the step
  bool collided = false;  ///< the commanded motion hit a wall and was cut short
  double distance = 0.0;  ///< arc length actually driven [m]
  double turned = 0.0;    ///< heading change actually made [rad]
};

/// True when a disc of `radius` at `centre` overlaps an occupied cell (exact disc-square test).
bool disc_collides(const World& world, const Eigen::Vector2d& centre, double radius);

/// Pose after driving (v, omega) for dt from p, on the exact arc (straight when omega = 0).
slam::Pose2 integrate_arc(const slam::Pose2& p, double v, double omega, double dt);

class Robot {
 public:
  /// Keeps a reference to `world`; throws std::invalid_argument if `start` collides.
  Robot(const World& world, const slam::Pose2& start, const RobotOptions& options = {});

  /// Drives (v [m/s], omega [rad/s]) for dt [s] > 0, clamped to the limits.
  StepResult step(double v, double omega, double dt);
  [[nodiscard]] const slam::Pose2& pose() const { return pose_; }
  [[nodiscard]] const RobotOptions& options() const { return o_; }

 private:
  const World* world_;
  RobotOptions o_;
  slam::Pose2 pose_;
};

}  // namespace lookahead::exploration
