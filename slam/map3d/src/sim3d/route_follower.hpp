// SPDX-License-Identifier: MIT
// The true motion along a route: drive straight at constant speed between waypoints, turn
// on the spot at each one. Internal to the simulator.
#pragma once

#include <vector>

#include "lookahead/slam/geometry/pose3.hpp"

namespace lookahead::slam::sim3d_detail {

struct TrueStep {
  Pose3 pose;               ///< robot base after the step
  double distance = 0.0;    ///< travelled during the step [m]
  double yaw_change = 0.0;  ///< [rad]
};

/// Steps of length dt until the last waypoint is reached.
std::vector<TrueStep> follow_route(const std::vector<Eigen::Vector3d>& route, double speed, double turn_rate,
                                   double dt);

}  // namespace lookahead::slam::sim3d_detail
