// SPDX-License-Identifier: MIT
// Turn, then creep: a robot whose body a wall corner pins (every forward step sweeps the
// disc into it) gets out, in the simulator, without touching the wall.
#include "lookahead/exploration/stop_escape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lookahead/exploration/laser_simulator.hpp"
#include "lookahead/exploration/robot.hpp"
#include "lookahead/exploration/swept_disc.hpp"

namespace lookahead::exploration {
namespace {

constexpr double kRadius = 0.1;

// A 4 m x 4 m room with a wall block whose top-left corner is at (2, 2).
World room_with_block() {
  World w(80, 80, 0.05, {0.0, 0.0}, World::kFree);
  w.fill_rect({0.0, 0.0}, {4.0, 0.1}, World::kOccupied);
  w.fill_rect({0.0, 3.9}, {4.0, 4.0}, World::kOccupied);
  w.fill_rect({0.0, 0.0}, {0.1, 4.0}, World::kOccupied);
  w.fill_rect({3.9, 0.0}, {4.0, 4.0}, World::kOccupied);
  w.fill_rect({2.0, 1.0}, {3.0, 2.0}, World::kOccupied);
  return w;
}

struct Room {
  World world = room_with_block();
  LaserOptions laser;
  EscapeLimits limits{kRadius, 0.2, 1.0, 0.1};
  explicit Room(double fov) {
    laser.fov = fov;
    laser.max_range = 8.0;
    laser.range_sigma = 0.0;
  }
};

// The robot 1.5 cm clear of the corner at (2, 2), facing along the block's top face so the
// corner sits ahead and to the right of its body: a forward step sweeps into it.
const slam::Pose2 kPinned{1.98, 2.105, -0.35};

TEST(StopEscape, APinnedRobotTurnsAndCreepsClearOfTheCorner) {
  for (const double fov : {2.0 * M_PI, M_PI}) {
    Room s(fov);
    LaserSimulator laser(s.world, s.laser);
    Robot robot(s.world, kPinned, {kRadius, 0.2, 1.0});
    slam::LaserScan scan = laser.scan(robot.pose(), 0.0);
    ASSERT_TRUE(disc_sweeps_into(scan, kRadius, {0.1, 0.0, 0.06})) << "the corner must pin the robot";

    StopEscape escape;
    EXPECT_FALSE(escape.start(scan, robot.pose(), s.limits)) << "not armed: no path to escape on";
    escape.arm();
    ASSERT_TRUE(escape.start(scan, robot.pose(), s.limits));
    int steps = 0;
    double driven = 0.0;
    while (escape.active() && steps < 200) {
      const planner::VelocityCommand cmd = escape.command(scan, robot.pose(), s.limits);
      const StepResult r = robot.step(cmd.v, cmd.omega, s.limits.period);
      ASSERT_FALSE(r.collided) << "fov " << fov << ", step " << steps;
      driven += r.distance;
      scan = laser.scan(robot.pose(), 0.1 * ++steps);
    }
    EXPECT_FALSE(escape.active()) << "the escape ends";
    EXPECT_NEAR(driven, 0.2, 0.03) << "it creeps its distance";
    // The block spans x in [2, 3], y in [1, 2]: the body's edge is 2 cm clear of it or more.
    const double dx = std::max(2.0 - robot.pose().x, 0.0), dy = std::max(robot.pose().y - 2.0, 0.0);
    EXPECT_GT(std::hypot(dx, dy), kRadius + 0.02) << "fov " << fov;
    // One escape per path: the next needs a new path.
    EXPECT_FALSE(escape.start(scan, kPinned, s.limits));
  }
}

TEST(StopEscape, ABoxedInRobotDoesNotStart) {
  // Walls 2 cm from the body all round: no heading is clear for the creep.
  World w(40, 40, 0.05, {0.0, 0.0}, World::kOccupied);
  w.fill_rect({0.88, 0.88}, {1.12, 1.12}, World::kFree);
  LaserOptions o;
  o.fov = 2.0 * M_PI;
  o.range_sigma = 0.0;
  LaserSimulator laser(w, o);
  StopEscape escape;
  escape.arm();
  EXPECT_FALSE(escape.start(laser.scan({1.0, 1.0, 0.0}, 0.0), {1.0, 1.0, 0.0}, {kRadius, 0.2, 1.0, 0.1}));
  EXPECT_FALSE(escape.active());
}

}  // namespace
}  // namespace lookahead::exploration
