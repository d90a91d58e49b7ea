// SPDX-License-Identifier: MIT
// The reactive stop of a robot that passes walls with centimetres to spare (a squeeze through
// a door the safety margin closes): the body is a disc, and what it sweeps in the next moment
// is the disc driven along the commanded arc, not a straight corridor ahead. Pure pursuit
// turns around a door jamb on an arc, and a straight corridor misses the jamb beside it.
#pragma once

#include <optional>

#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

/// The disc motion to check: forward speed v > 0 [m/s], turn rate omega [rad/s], over this
/// distance along the arc [m].
struct DiscMotion {
  double v = 0.0;
  double omega = 0.0;
  double distance = 0.0;
};

/// True when a laser end point of `scan` (robot frame, the laser at its offset) comes nearer
/// than `radius` to the disc's centre somewhere along the motion, and nearer than it is now:
/// a wall the robot is driving into. Walls beside the body that the motion does not approach
/// do not count, so the robot may drive along a jamb 1 cm away.
bool disc_sweeps_into(const slam::LaserScan& scan, double radius, const DiscMotion& motion);

/// The heading [rad, robot frame] nearest `preferred` (tried 10 deg apart, either side)
/// along which the disc drives `distance` [m] straight without sweeping into a return,
/// among the headings the scan covers; none when every one is blocked. The way out of a
/// corner the body touches: the robot turns to it on the spot and creeps (stop_escape.hpp).
std::optional<double> clear_heading(const slam::LaserScan& scan, double radius, double distance, double preferred);

/// True when a laser end point of `scan` lies ahead of the robot (x > 0) within `reach` [m]
/// and less than `half_width` [m] to either side: the straight corridor the reactive stop
/// checks where walls are not centimetres away.
bool corridor_holds_return(const slam::LaserScan& scan, double half_width, double reach);

}  // namespace lookahead::exploration
