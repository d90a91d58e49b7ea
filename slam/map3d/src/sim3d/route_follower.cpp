// SPDX-License-Identifier: MIT
#include "route_follower.hpp"

#include <algorithm>
#include <cmath>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::sim3d_detail {

std::vector<TrueStep> follow_route(const std::vector<Eigen::Vector3d>& route, double speed, double turn_rate,
                                   double dt) {
  std::vector<TrueStep> steps;
  if (route.size() < 2) return steps;
  Eigen::Vector3d p = route[0];
  double yaw = std::atan2(route[1].y() - p.y(), route[1].x() - p.x());
  double pitch = 0.0;
  for (std::size_t next = 1; next < route.size();) {
    const Eigen::Vector3d to_go = route[next] - p;
    if (to_go.norm() < 1e-9) {
      ++next;
      continue;
    }
    TrueStep s;
    const double heading = std::atan2(to_go.y(), to_go.x());
    const double error = normalize_angle(heading - yaw);
    if (to_go.head<2>().norm() > 1e-6 && std::abs(error) > 1e-6) {
      s.yaw_change = std::clamp(error, -turn_rate * dt, turn_rate * dt);
      yaw = normalize_angle(yaw + s.yaw_change);
    } else {
      s.distance = std::min(speed * dt, to_go.norm());
      p += to_go.normalized() * s.distance;
      pitch = -std::atan2(to_go.z(), to_go.head<2>().norm());  // nose up is negative pitch
    }
    s.pose = make_pose3(p, {0.0, pitch, yaw});
    steps.push_back(s);
  }
  return steps;
}

}  // namespace lookahead::slam::sim3d_detail
