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

// Headings an escape tries, this far apart [rad] (10 deg): around a corner the body touches,
// the clear headings span tens of degrees.
constexpr double kHeadingStep = M_PI / 18.0;

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

// A robot turned to `heading` (robot frame) drives its disc along an arc of curvature k for
// `distance`: does the disc come nearer than `radius` to an end point of `scan`, and nearer
// than that point is now? The end points are turned into the robot's new frame one by one.
bool sweeps_into(const slam::LaserScan& scan, double heading, double radius, double k, double distance) {
  std::vector<Point> centres;
  for (double s = kStep; s < distance + kStep; s += kStep) centres.push_back(centre_after(std::min(s, distance), k));
  const double r2 = radius * radius;
  const double near2 = (distance + radius) * (distance + radius);
  const double cos_h = std::cos(heading), sin_h = std::sin(heading);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.is_return(i)) continue;
    const Point e = end_point(scan, i);
    const Point p{cos_h * e.x + sin_h * e.y, -sin_h * e.x + cos_h * e.y};
    const double now2 = p.x * p.x + p.y * p.y;
    if (now2 > near2) continue;  // out of reach of this motion
    for (const Point& c : centres) {
      const double d2 = (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
      if (d2 < r2 && d2 < now2) return true;
    }
  }
  return false;
}

// Is `heading` (robot frame) within the bearings the scan covers?
bool seen(const slam::LaserScan& scan, double heading) {
  if (scan.ranges.empty()) return false;
  const double span = scan.angle_increment * static_cast<double>(scan.ranges.size());
  if (span >= 2.0 * M_PI - 1e-6) return true;
  const double from_first = std::remainder(heading - scan.laser_offset.theta - scan.angle_min, 2.0 * M_PI);
  const double wrapped = from_first < 0 ? from_first + 2.0 * M_PI : from_first;
  return wrapped <= span;
}

}  // namespace

bool disc_sweeps_into(const slam::LaserScan& scan, double radius, const DiscMotion& motion) {
  if (motion.v <= 0.0 || motion.distance <= 0.0) return false;
  return sweeps_into(scan, 0.0, radius, motion.omega / motion.v, motion.distance);
}

std::optional<double> clear_heading(const slam::LaserScan& scan, double radius, double distance, double preferred) {
  // Nearest first: preferred, then 10 deg either side, 20 deg, ... up to half a turn.
  const int steps = static_cast<int>(M_PI / kHeadingStep);
  for (int k = 0; k <= steps; ++k) {
    for (const int sign : {1, -1}) {
      const double heading = std::remainder(preferred + sign * k * kHeadingStep, 2.0 * M_PI);
      if (!seen(scan, heading)) continue;
      if (!sweeps_into(scan, heading, radius, 0.0, distance)) return heading;
      if (k == 0) break;
    }
  }
  return std::nullopt;
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
