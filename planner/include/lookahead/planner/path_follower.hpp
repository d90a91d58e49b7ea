// SPDX-License-Identifier: MIT
// Pure-pursuit path following for a unicycle (differential drive): Coulter, "Implementation
// of the Pure Pursuit Path Tracking Algorithm", CMU-RI-TR-92-01, 1992. Each step picks a
// look-ahead point on the path and drives the arc through it: curvature kappa = 2 y / L^2
// (Sec. 2), y being the point's lateral offset in the robot frame and L its distance.
//
// Deviations:
//  - The look-ahead point lies `lookahead` metres of arc length beyond the robot's projection
//    on the path, not on the circle of radius L around the robot: it always exists and is
//    unique, even when the robot is farther than L from the path.
//  - When the heading error to that point exceeds `rotate_in_place_angle`, the robot turns
//    on the spot first: plan() paths have sharp corners that an arc would cut.
//  - Speed is capped so the turn rate never exceeds its limit (the arc is kept, slower), and
//    tapers near the goal so the robot stops within the tolerance.
#pragma once

#include <cstddef>

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path.hpp"
#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::planner {

struct FollowerOptions {
  double lookahead = 0.5;              ///< L, arc length ahead of the robot [m], (0, 10]
  double max_linear_speed = 0.5;       ///< [m/s], (0, 5]
  double max_turn_rate = 1.0;          ///< [rad/s], (0, 10]
  double rotate_in_place_angle = 0.8;  ///< heading error that stops forward motion [rad], (0, pi]
  double goal_tolerance = 0.1;         ///< done within this distance of the last waypoint [m], (0, 5]
  /// Speed near the goal: v <= approach_gain * distance to goal [1/s], (0, 100].
  double approach_gain = 1.0;
};

/// Throws std::invalid_argument naming the field and value when an option is out of range.
void validate(const FollowerOptions& options);

/// Velocity command for a unicycle.
struct VelocityCommand {
  double v = 0.0;      ///< forward speed [m/s], >= 0
  double omega = 0.0;  ///< turn rate [rad/s], counter-clockwise positive
};

class PathFollower {
 public:
  /// The path must hold at least one waypoint (throws std::invalid_argument otherwise).
  explicit PathFollower(Path path, const FollowerOptions& options = {});

  /// The command for the current pose. Progress along the path only moves forward, so a
  /// path that passes near itself is not cut short. Returns zero once the goal is reached.
  [[nodiscard]] VelocityCommand command(const slam::Pose2& pose);

  [[nodiscard]] bool goal_reached() const { return goal_reached_; }
  /// The part of the path still ahead, from the robot's projection to the goal, is free on
  /// this costmap (kPlanning: with the safety margin the plan kept; kBody: the body alone
  /// fits, Costmap::path_fits_body). False means replan: new map data blocked it. A first
  /// stretch (up to 0.5 m) leading from inside the inflated band out to free space is not
  /// checked: it is the robot's way back out after cutting a corner, not a blocked path.
  enum class Clearance { kPlanning, kBody };
  [[nodiscard]] bool path_still_valid(const Costmap& costmap, Clearance clearance = Clearance::kPlanning) const;

  [[nodiscard]] const Path& path() const { return path_; }
  /// Index of the segment the robot's projection is on (segment i joins waypoints i, i+1).
  [[nodiscard]] std::size_t segment() const { return segment_; }
  /// The robot's projection on the path (the start of the remaining path).
  [[nodiscard]] Point2 projection() const { return projection_; }
  /// Arc length from the robot's projection to the goal [m].
  [[nodiscard]] double remaining_length() const;

 private:
  void advance_projection(Point2 robot);
  [[nodiscard]] Point2 lookahead_point() const;

  Path path_;
  FollowerOptions options_;
  std::size_t segment_ = 0;
  Point2 projection_;
  bool goal_reached_ = false;
};

}  // namespace lookahead::planner
