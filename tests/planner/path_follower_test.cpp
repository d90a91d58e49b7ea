// SPDX-License-Identifier: MIT
#include "lookahead/planner/path_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/planner/plan.hpp"
#include "test_worlds.hpp"

namespace lookahead::planner {
namespace {

using slam::Pose2;

/// Distance from p to the polyline.
double distance_to_path(const Path& path, Point2 p) {
  double best = distance(p, path.front());
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Point2 a = path[i - 1];
    const Point2 b = path[i];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, distance(p, {a.x + t * dx, a.y + t * dy}));
  }
  return best;
}

/// Exact unicycle motion over dt for constant (v, omega).
Pose2 integrate(const Pose2& p, const VelocityCommand& c, double dt) {
  if (std::fabs(c.omega) < 1e-9) {
    return {p.x + c.v * dt * std::cos(p.theta), p.y + c.v * dt * std::sin(p.theta), p.theta};
  }
  const double theta = p.theta + c.omega * dt;
  const double r = c.v / c.omega;
  return {p.x + r * (std::sin(theta) - std::sin(p.theta)), p.y - r * (std::cos(theta) - std::cos(p.theta)),
          slam::normalize_angle(theta)};
}

// An L-shaped corridor, 1 m wide, along the path (0.5,0.5) -> (3.5,0.5) -> (3.5,3.5). The
// robot starts facing away from the first leg, so it must turn on the spot first.
TEST(PathFollower, DrivesUnicycleAlongLShapedPathInsideCorridor) {
  const Path path{{0.5, 0.5}, {3.5, 0.5}, {3.5, 3.5}};
  const FollowerOptions o;
  PathFollower follower(path, o);
  Pose2 pose{0.5, 0.5, 2.5};
  const double dt = 0.05;
  double worst_offset = 0.0;
  int steps = 0;
  for (; steps < 4000 && !follower.goal_reached(); ++steps) {
    const VelocityCommand c = follower.command(pose);
    ASSERT_GE(c.v, 0.0);
    ASSERT_LE(c.v, o.max_linear_speed + 1e-12);
    ASSERT_LE(std::fabs(c.omega), o.max_turn_rate + 1e-12);
    pose = integrate(pose, c, dt);
    worst_offset = std::max(worst_offset, distance_to_path(path, {pose.x, pose.y}));
    ASSERT_LT(worst_offset, 0.5) << "left the corridor at step " << steps;
  }
  EXPECT_TRUE(follower.goal_reached());
  EXPECT_LT(distance({pose.x, pose.y}, path.back()), o.goal_tolerance + 1e-9);
  // 6 m at 0.5 m/s is 12 s = 240 steps; turning and the slow approach add some.
  EXPECT_LT(steps, 600);
  RecordProperty("worst_offset_mm", static_cast<int>(worst_offset * 1000));
  const VelocityCommand stop = follower.command(pose);
  EXPECT_EQ(stop.v, 0.0);
  EXPECT_EQ(stop.omega, 0.0);
}

// The path left (the stuck clock's measure of progress around a wall) shrinks as the robot
// drives along the L, from its whole length to zero at the goal, and never grows.
TEST(PathFollower, PathLeftShrinksAlongTheWayToZero) {
  const Path path{{0.5, 0.5}, {3.5, 0.5}, {3.5, 3.5}};
  PathFollower follower(path, FollowerOptions{});
  EXPECT_NEAR(follower.remaining_length(), 6.0, 1e-9);
  Pose2 pose{0.5, 0.5, 0.0};
  double last = follower.remaining_length();
  for (int steps = 0; steps < 4000 && !follower.goal_reached(); ++steps) {
    pose = integrate(pose, follower.command(pose), 0.05);
    ASSERT_LE(follower.remaining_length(), last + 1e-9) << "step " << steps;
    last = follower.remaining_length();
    if (std::fabs(pose.x - 2.0) < 0.01 && pose.y < 1.0) EXPECT_NEAR(last, 4.5, 0.1);
  }
  EXPECT_TRUE(follower.goal_reached());
  EXPECT_LT(follower.remaining_length(), 0.15);  // the goal tolerance (0.1 m) from the projection
}

// Planner and follower together: the robot's disc never touches a wall of the gap world.
TEST(PathFollower, FollowsAPlannedPathThroughTheGapWithoutTouchingWalls) {
  set_ompl_log_level(OmplLogLevel::kWarn);
  const slam::OccupancyGrid g = testing::corridor_with_gap();
  PlannerOptions po;
  po.max_samples = 3000;
  po.time_budget = 20.0;
  const PlanResult planned = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, po);
  ASSERT_TRUE(planned.solved()) << planned.message;
  // Walls inflated by 0.15 m only: the robot (0.25 m) may stray 0.1 m from the planned path.
  CostmapOptions touching;
  touching.robot_radius = 0.15;
  const Costmap walls(g, touching);
  PathFollower follower(planned.path);
  Pose2 pose{0.5, 0.5, 0.0};
  int steps = 0;
  for (; steps < 4000 && !follower.goal_reached(); ++steps) {
    pose = integrate(pose, follower.command(pose), 0.05);
    ASSERT_TRUE(walls.is_free(pose.x, pose.y)) << "at " << pose.x << "," << pose.y;
  }
  EXPECT_TRUE(follower.goal_reached());
}

TEST(PathFollower, RotatesInPlaceWhenHeadingErrorIsLarge) {
  PathFollower follower({{0.0, 0.0}, {2.0, 0.0}});
  const VelocityCommand c = follower.command(Pose2{0.0, 0.0, M_PI / 2});  // facing left of it
  EXPECT_EQ(c.v, 0.0);
  EXPECT_LT(c.omega, 0.0);  // clockwise, the short way round
}

TEST(PathFollower, PathStillValidUntilAnObstacleAppearsAhead) {
  using testing::fill;
  slam::OccupancyGrid g = testing::walled_room();
  CostmapOptions co;
  co.robot_radius = 0.1;
  const Path path{{0.5, 0.5}, {3.5, 0.5}, {3.5, 2.5}};
  PathFollower follower(path);
  EXPECT_TRUE(follower.path_still_valid(Costmap(g, co)));
  // New map data: a box on the second leg.
  fill(g, 68, 30, 72, 34, true);
  EXPECT_FALSE(follower.path_still_valid(Costmap(g, co)));
  // Once the robot is past that leg's start... only what lies ahead counts: a box behind.
  slam::OccupancyGrid behind = testing::walled_room();
  fill(behind, 15, 8, 17, 12, true);
  (void)follower.command(Pose2{2.0, 0.5, 0.0});
  EXPECT_TRUE(follower.path_still_valid(Costmap(behind, co)));
}

// Regression (kth_0510034869): a robot that cut a door jamb stands inside the inflated band,
// and its plan starts with the stretch back out. That stretch is the way out, not new walls:
// treating it as blocked replanned at every map refresh while the robot turned on the spot.
TEST(PathFollower, TheWayOutOfTheInflatedBandIsNoBlockedPath) {
  CostmapOptions co;
  co.robot_radius = 0.18;
  const Costmap cm(testing::walled_room(), co);
  ASSERT_FALSE(cm.is_free(Point2{0.1, 1.5}));  // 0.125 m from the left wall: inflated
  ASSERT_TRUE(cm.is_free(Point2{0.3, 1.5}));
  PathFollower out_of_band({{0.1, 1.5}, {0.3, 1.5}, {3.0, 1.5}});
  EXPECT_TRUE(out_of_band.path_still_valid(cm));
  // A path that stays in the band for more than the escape length is blocked.
  PathFollower along_wall({{0.1, 0.5}, {0.1, 2.5}});
  EXPECT_FALSE(along_wall.path_still_valid(cm));
  // So is one whose way out ends in a wall further on.
  slam::OccupancyGrid boxed = testing::walled_room();
  testing::fill(boxed, 30, 20, 34, 40, true);  // a box across x = 1.5..1.75 m
  EXPECT_FALSE(out_of_band.path_still_valid(Costmap(boxed, co)));
}

// A door the margin closes and opens again with every scan: a path may be checked with the
// body alone, which still fits where the margin closes.
TEST(PathFollower, ThePathStaysValidForTheBodyWhereOnlyTheMarginCloses) {
  using Clearance = PathFollower::Clearance;
  CostmapOptions co;
  co.robot_radius = 0.3;
  co.safety_margin = 0.1;
  slam::OccupancyGrid g = testing::walled_room();
  const PathFollower follower({{0.5, 1.475}, {3.5, 1.475}});
  EXPECT_TRUE(follower.path_still_valid(Costmap(g, co)));
  testing::fill(g, 40, 34, 44, 40, true);  // a box whose edge ends 0.25 m beside the path
  EXPECT_FALSE(follower.path_still_valid(Costmap(g, co), Clearance::kPlanning));
  EXPECT_TRUE(follower.path_still_valid(Costmap(g, co), Clearance::kBody));
  testing::fill(g, 40, 33, 44, 33, true);  // now 0.2 m: the body no longer fits
  EXPECT_FALSE(follower.path_still_valid(Costmap(g, co), Clearance::kBody));
}

TEST(PathFollower, RejectsEmptyPathAndBadOptions) {
  EXPECT_THROW(PathFollower(Path{}), std::invalid_argument);
  FollowerOptions o;
  o.lookahead = 0.0;
  EXPECT_THROW(PathFollower(Path{{0, 0}}, o), std::invalid_argument);
  o = {};
  o.max_turn_rate = -1.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::planner
