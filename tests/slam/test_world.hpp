// SPDX-License-Identifier: MIT
// A small polygonal world for unit tests: walls as segments, and an exact laser simulator
// (ray-segment intersection), so tests know the true poses and the true map.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam::test {

struct Segment {
  double x0, y0, x1, y1;
};

/// A 10 m x 6 m room with an inner box and a pillar: enough structure to pin every axis.
inline std::vector<Segment> room_world() {
  return {{0, 0, 10, 0},    {10, 0, 10, 6}, {10, 6, 0, 6},  {0, 6, 0, 0},   {3, 2, 5, 2},       {5, 2, 5, 3.5},
          {5, 3.5, 3, 3.5}, {3, 3.5, 3, 2}, {7.5, 4, 8, 4}, {8, 4, 8, 4.6}, {8, 4.6, 7.5, 4.6}, {7.5, 4.6, 7.5, 4}};
}

inline double cast(const std::vector<Segment>& world, double x, double y, double a, double max) {
  const double dx = std::cos(a), dy = std::sin(a);
  double best = max;
  for (const Segment& s : world) {
    const double ex = s.x1 - s.x0, ey = s.y1 - s.y0;
    const double den = dx * ey - dy * ex;
    if (std::abs(den) < 1e-12) continue;
    const double t = ((s.x0 - x) * ey - (s.y0 - y) * ex) / den;
    const double u = ((s.x0 - x) * dy - (s.y0 - y) * dx) / den;
    if (t > 0 && u >= 0 && u <= 1 && t < best) best = t;
  }
  return best;
}

/// A 180-beam, 1-degree scan from `truth` (laser at the robot origin), reporting `odometry`.
inline LaserScan simulate_scan(const std::vector<Segment>& world, const Pose2& truth, const Pose2& odometry,
                               double t = 0.0) {
  LaserScan s;
  s.timestamp = t;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 180;
  s.max_range = 80.0;
  s.odometry = odometry;
  for (int i = 0; i < 180; ++i) {
    const double r = cast(world, truth.x, truth.y, truth.theta + s.bearing(static_cast<std::size_t>(i)), 80.0);
    s.ranges.push_back(r >= 80.0 ? std::numeric_limits<float>::infinity() : static_cast<float>(r));
  }
  return s;
}

}  // namespace lookahead::slam::test
