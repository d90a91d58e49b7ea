// SPDX-License-Identifier: MIT
#include "lookahead/exploration/swept_disc.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lookahead::exploration {
namespace {

// Spacing of the centre positions checked along the arc [m]: a fifth of the 0.1 m bodies
// of the KTH setups, so a wall tip cannot pass between two of them unseen.
constexpr double kStep = 0.02;

struct Point {
  double x, y;
};

// Centre of the disc after driving s metres along an arc of curvature k, from the origin
// facing +x (the robot frame).
Point centre_after(double s, double k) {
  if (std::abs(k) < 1e-9) return {s, 0.0};
  return {std::sin(k * s) / k, (1.0 - std::cos(k * s)) / k};
}

// End point of beam i in the robot frame (the laser at its offset).
Point end_point(const slam::LaserScan& scan, std::size_t i) {
  const double a = scan.bearing(i) + scan.laser_offset.theta;
  return {scan.laser_offset.x + scan.ranges[i] * std::cos(a), scan.laser_offset.y + scan.ranges[i] * std::sin(a)};
}

}  // namespace

bool disc_sweeps_into(const slam::LaserScan& scan, double radius, const DiscMotion& motion) {
  if (motion.v <= 0.0 || motion.distance <= 0.0) return false;
  const double k = motion.omega / motion.v;
  std::vector<Point> centres;
  for (double s = kStep; s < motion.distance + kStep; s += kStep)
    centres.push_back(centre_after(std::min(s, motion.distance), k));
  const double r2 = radius * radius;
  const double near2 = (motion.distance + radius) * (motion.distance + radius);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.is_return(i)) continue;
    const Point p = end_point(scan, i);
    const double now2 = p.x * p.x + p.y * p.y;
    if (now2 > near2) continue;  // out of reach of this motion
    for (const Point& c : centres) {
      const double d2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
      if (d2 < r2 && d2 < now2) return true;
    }
  }
  return false;
}

bool corridor_holds_return(const slam::LaserScan& scan, double half_width, double reach) {
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.is_return(i)) continue;
    const Point p = end_point(scan, i);
    if (p.x > 0 && p.x < reach && std::abs(p.y) < half_width) return true;
  }
  return false;
}

}  // namespace lookahead::exploration
