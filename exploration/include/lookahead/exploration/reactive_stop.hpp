// SPDX-License-Identifier: MIT
// The reactive stop, the Follow state's guard: no forward motion into laser returns the map
// has not caught up with, and the path given up when the stop holds the robot for long (the
// Follow -> Replan transition, navigation_state_machine.hpp).
#pragma once

#include "lookahead/planner/path_follower.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

/// What the stop looks at: the latest scan, the body and the commanded step.
struct StopGeometry {
  double robot_radius = 0.25;   ///< [m]
  double stop_distance = 0.15;  ///< ahead of the body, beyond the step's travel [m]
  double period = 0.1;          ///< one laser period [s]
  /// Half through a door the margin closes (after a squeeze): the swept disc is tested, not
  /// a corridor with side clearance.
  bool tight = false;
};

class ReactiveStop {
 public:
  /// Does the commanded step run the body into a laser return?
  [[nodiscard]] static bool blocks(const slam::LaserScan& scan, const planner::VelocityCommand& cmd,
                                   const StopGeometry& geometry);
  /// Counts one step held by the stop. True when the hold has lasted long enough that the
  /// path is to be given up and replanned; `must_wait`: the path is the only way (a
  /// backtrack, a squeeze), so the robot waits and the stuck clock gives the goal up.
  bool hold(bool must_wait);
  void clear() { held_ = 0; }  ///< the robot drives on, or has no path
  /// The stop held the robot at its last step.
  [[nodiscard]] bool holding() const { return held_ > 0; }
  /// The hold has lasted long enough for a turn-then-creep escape (stop_escape.hpp), half
  /// the time before the path is given up.
  [[nodiscard]] bool escape_due() const;

 private:
  int held_ = 0;  ///< consecutive steps the stop has held the robot
};

}  // namespace lookahead::exploration
