// SPDX-License-Identifier: MIT
// The reactive stop of a squeeze: the disc driven along the commanded arc.
#include "lookahead/exploration/swept_disc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace lookahead::exploration {
namespace {

struct Return {
  double x, y;
};

// A scan with one beam per end point (robot frame, laser at the robot's centre).
slam::LaserScan scan_of(const std::vector<Return>& points) {
  slam::LaserScan scan;
  scan.max_range = 30.0;
  scan.angle_min = 0.0;
  scan.angle_increment = 0.0;
  for (const Return& p : points) {
    scan.ranges.push_back(static_cast<float>(std::hypot(p.x, p.y)));
  }
  return scan;
}

// bearing(i) is angle_min + i * increment: one scan per point keeps each bearing exact.
bool sweeps_into(Return p, double v, double omega) {
  slam::LaserScan scan = scan_of({p});
  scan.angle_min = std::atan2(p.y, p.x);
  return disc_sweeps_into(scan, 0.1, {v, omega, 0.17});
}

TEST(SweptDisc, AWallAheadStopsTheRobot) {
  EXPECT_TRUE(sweeps_into({0.2, 0.0}, 0.2, 0.0));
  EXPECT_TRUE(sweeps_into({0.25, 0.05}, 0.2, 0.0));
  EXPECT_FALSE(sweeps_into({0.4, 0.0}, 0.2, 0.0));  // beyond the stop distance
}

TEST(SweptDisc, AJambBesideTheBodyDoesNotHoldIt) {
  // A door 1.3 cm wider than the body on this side: its jamb runs beside the robot.
  for (double x = -0.1; x <= 0.3; x += 0.02) {
    EXPECT_FALSE(sweeps_into({x, 0.113}, 0.2, 0.0)) << x;
    EXPECT_FALSE(sweeps_into({x, -0.113}, 0.2, 0.0)) << x;
  }
}

TEST(SweptDisc, AnArcTurningIntoAJambIsStoppedWhereAStraightCorridorIsNot) {
  // Ahead and 11 cm to the left: clear of a straight corridor the body's width, hit when
  // pure pursuit turns left on a 0.25 m arc.
  const Return tip{0.08, 0.11};
  EXPECT_FALSE(sweeps_into(tip, 0.2, 0.0));
  EXPECT_TRUE(sweeps_into(tip, 0.2, 0.8));
  EXPECT_FALSE(sweeps_into(tip, 0.2, -0.8));  // turning away from it
}

TEST(SweptDisc, TheStraightCorridorHoldsReturnsAheadWithinItsWidthAndReach) {
  auto holds = [](Return p, double half_width) {
    slam::LaserScan scan = scan_of({p});
    scan.angle_min = std::atan2(p.y, p.x);
    return corridor_holds_return(scan, half_width, 0.37);
  };
  EXPECT_TRUE(holds({0.2, 0.11}, 0.12));
  EXPECT_FALSE(holds({0.2, 0.11}, 0.10));   // beside a corridor the body's width
  EXPECT_FALSE(holds({0.5, 0.0}, 0.12));    // beyond the reach
  EXPECT_FALSE(holds({-0.05, 0.0}, 0.12));  // behind the robot
  // The jamb the arc turns into (below) is outside a straight corridor the body's width.
  EXPECT_FALSE(holds({0.08, 0.11}, 0.10));
}

TEST(SweptDisc, AReturnTheRobotMovesAwayFromDoesNotCount) {
  EXPECT_FALSE(sweeps_into({-0.05, 0.0}, 0.2, 0.0));  // touching the back of the body
  EXPECT_FALSE(sweeps_into({0.0, 0.0}, 0.0, 0.0));    // not moving
}

// A scan of every beam at `count` bearings from angle_min, `increment` apart, reading far
// (no return) except the given end points, each on its nearest beam.
slam::LaserScan fan_of(const std::vector<Return>& points, double angle_min, double increment, int count) {
  slam::LaserScan scan;
  scan.max_range = 30.0;
  scan.angle_min = angle_min;
  scan.angle_increment = increment;
  scan.ranges.assign(static_cast<std::size_t>(count), 30.0F);
  for (const Return& p : points) {
    const double from_first = std::remainder(std::atan2(p.y, p.x) - angle_min, 2.0 * M_PI);
    const long beam = std::lround((from_first < 0 ? from_first + 2.0 * M_PI : from_first) / increment);
    if (beam >= 0 && beam < count)
      scan.ranges[static_cast<std::size_t>(beam)] = static_cast<float>(std::hypot(p.x, p.y));
  }
  return scan;
}

TEST(SweptDisc, TheClearHeadingNearestThePreferredOneIsFound) {
  const double step = M_PI / 360.0;
  // Nothing near: the preferred heading itself.
  EXPECT_NEAR(*clear_heading(fan_of({}, -M_PI, step, 720), 0.1, 0.25, 0.3), 0.3, 1e-12);
  // A corner 2 cm from the body, ahead and to the right: straight on is blocked, the way out
  // turns left, and not further than it must.
  const slam::LaserScan corner = fan_of({{0.09, -0.07}, {0.1, -0.08}, {0.2, -0.08}}, -M_PI, step, 720);
  ASSERT_TRUE(disc_sweeps_into(corner, 0.1, {0.1, 0.0, 0.25}));
  const auto out = clear_heading(corner, 0.1, 0.25, 0.0);
  ASSERT_TRUE(out.has_value());
  EXPECT_GT(*out, 0.0);
  EXPECT_LT(*out, M_PI / 2);
}

TEST(SweptDisc, NoHeadingIsClearInsideARingOfWalls) {
  std::vector<Return> ring;
  for (int k = 0; k < 72; ++k) ring.push_back({0.12 * std::cos(k * M_PI / 36), 0.12 * std::sin(k * M_PI / 36)});
  EXPECT_FALSE(clear_heading(fan_of(ring, -M_PI, M_PI / 360.0, 720), 0.1, 0.25, 0.0).has_value());
}

TEST(SweptDisc, AHalfCircleLaserOffersNoHeadingBehindTheRobot) {
  // A 180 deg laser facing forward; a wall right in front: only headings the scan covers
  // (within 90 deg either side) are offered, never the unseen way back.
  std::vector<Return> wall;
  for (double y = -1.0; y <= 1.0; y += 0.01) wall.push_back({0.12, y});
  const auto out = clear_heading(fan_of(wall, -M_PI / 2, M_PI / 180.0, 181), 0.1, 0.25, 0.0);
  ASSERT_TRUE(out.has_value());
  EXPECT_LE(std::abs(*out), M_PI / 2 + 1e-9);
}

}  // namespace
}  // namespace lookahead::exploration
