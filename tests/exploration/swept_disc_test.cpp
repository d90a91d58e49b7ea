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

}  // namespace
}  // namespace lookahead::exploration
