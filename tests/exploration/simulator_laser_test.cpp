// SPDX-License-Identifier: MIT
// The simulated laser against an analytic oracle: the distance to the walls of a box.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lookahead/exploration/laser_simulator.hpp"

namespace lookahead::exploration {
namespace {

// Exact distance from p along angle a to the boundary of [0, sx] x [0, sy], or to the wall
// slab x in [wall_x, wall_x + 0.5) when it is in the way.
double box_distance(double px, double py, double a, double sx, double sy, double wall_x) {
  const double dx = std::cos(a), dy = std::sin(a);
  double t = std::numeric_limits<double>::infinity();
  if (dx > 1e-12) t = std::min({t, (sx - px) / dx, (wall_x - px) / dx});
  if (dx < -1e-12) t = std::min(t, -px / dx);
  if (dy > 1e-12) t = std::min(t, (sy - py) / dy);
  if (dy < -1e-12) t = std::min(t, -py / dy);
  return t;
}

World box_with_wall() {
  World w(200, 160, 0.05, {0.0, 0.0}, World::kFree);  // 10 m x 8 m; outside is occupied
  w.fill_rect({6.0, 0.0}, {6.5, 8.0}, World::kOccupied);
  return w;
}

TEST(LaserSimulator, RangesMatchTheExactWallDistance) {
  const World w = box_with_wall();
  LaserOptions o;
  o.range_sigma = 0.0;
  o.max_range = 20.0;
  LaserSimulator laser(w, o);
  const slam::Pose2 pose{3.0, 4.3, 0.3};
  const slam::LaserScan s = laser.scan(pose, 1.5);
  ASSERT_EQ(s.ranges.size(), 181u);
  EXPECT_DOUBLE_EQ(s.angle_min, -M_PI / 2);
  EXPECT_DOUBLE_EQ(s.timestamp, 1.5);
  for (std::size_t i = 0; i < s.ranges.size(); ++i) {
    const double want = box_distance(pose.x, pose.y, pose.theta + s.bearing(i), 10.0, 8.0, 6.0);
    EXPECT_NEAR(s.ranges[i], want, 1e-5) << "beam " << i;  // float storage
  }
  EXPECT_NEAR(laser.cast({3.0, 4.0}, 0.0), 3.0, 1e-12);
  EXPECT_NEAR(laser.cast({3.0, 4.0}, M_PI), 3.0, 1e-12);
  EXPECT_NEAR(laser.cast({3.0, 4.0}, -M_PI / 2), 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(laser.cast({6.2, 4.0}, 0.0), 0.0);  // inside the wall
}

TEST(LaserSimulator, NoiseHasTheConfiguredSigma) {
  const World w = box_with_wall();
  LaserOptions o;
  o.range_sigma = 0.02;
  LaserSimulator laser(w, o);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int k = 0; k < 200; ++k) {
    const slam::LaserScan s = laser.scan({3.0, 4.0, 0.0}, 0.0);
    for (std::size_t i = 60; i <= 120; ++i) {  // beams that hit the wall at x = 6 (<= 5 m)
      const double e = s.ranges[i] - box_distance(3.0, 4.0, s.bearing(i), 10.0, 8.0, 6.0);
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0.0, 0.002);
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.02, 0.001);
}

TEST(LaserSimulator, BeyondMaxRangeIsANoReturn) {
  const World w = box_with_wall();
  LaserOptions o;
  o.max_range = 1.0;
  LaserSimulator laser(w, o);
  const slam::LaserScan s = laser.scan({3.0, 4.0, 0.0}, 0.0);
  for (std::size_t i = 0; i < s.ranges.size(); ++i) {
    EXPECT_FLOAT_EQ(s.ranges[i], 1.0f);
    EXPECT_FALSE(s.is_return(i));
  }
  EXPECT_TRUE(std::isinf(laser.cast({3.0, 4.0}, 0.0)));
}

TEST(LaserSimulator, SameSeedSameScanAndOptionsAreValidated) {
  const World w = box_with_wall();
  LaserSimulator a(w), b(w);
  EXPECT_EQ(a.scan({3, 4, 0}, 0).ranges, b.scan({3, 4, 0}, 0).ranges);
  LaserOptions o;
  o.angular_resolution = 0.5 * M_PI / 180;
  EXPECT_EQ(o.beam_count(), 361);
  o.fov = 2 * M_PI;
  o.angular_resolution = M_PI / 180;
  EXPECT_EQ(o.beam_count(), 360);
  o.max_range = -1;
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::exploration
