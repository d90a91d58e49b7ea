// SPDX-License-Identifier: MIT
// Robot kinematics and collisions, and the odometry drift statistics.
#include <gtest/gtest.h>

#include <cmath>

#include "lookahead/exploration/odometry_model.hpp"
#include "lookahead/exploration/robot.hpp"

namespace lookahead::exploration {
namespace {

World corridor_with_end_wall() {
  World w(200, 80, 0.05, {0.0, 0.0}, World::kFree);  // 10 m x 4 m
  w.fill_rect({6.0, 0.0}, {6.2, 4.0}, World::kOccupied);
  return w;
}

TEST(Robot, StopsAtAWall) {
  const World w = corridor_with_end_wall();
  Robot robot(w, {3.0, 2.0, 0.0});
  bool collided = false;
  for (int k = 0; k < 300 && !collided; ++k) collided = robot.step(0.5, 0.0, 0.1).collided;
  ASSERT_TRUE(collided);
  // The disc's front is within one collision step of the wall face at x = 6.
  EXPECT_LE(robot.pose().x, 6.0 - 0.25);
  EXPECT_GE(robot.pose().x, 6.0 - 0.25 - robot.options().collision_step);
  const StepResult again = robot.step(0.2, 0.0, 0.1);
  EXPECT_TRUE(again.collided);
  EXPECT_DOUBLE_EQ(again.distance, 0.0);
  EXPECT_FALSE(robot.step(-0.2, 0.0, 0.1).collided);  // backing off is free
}

TEST(Robot, ClampsToTheLimits) {
  const World w = corridor_with_end_wall();
  Robot robot(w, {1.0, 2.0, 0.0});
  const StepResult r = robot.step(5.0, 10.0, 0.1);
  EXPECT_NEAR(r.distance, robot.options().max_speed * 0.1, 1e-12);
  EXPECT_NEAR(r.turned, robot.options().max_turn_rate * 0.1, 1e-12);
}

TEST(Robot, ArcIntegrationIsExact) {
  // A full circle returns to the start; a quarter circle of radius v/omega ends where
  // geometry says it must.
  const slam::Pose2 p{1.0, 2.0, 0.5};
  const slam::Pose2 q = integrate_arc(p, 0.2, 0.5, 2 * M_PI / 0.5);
  EXPECT_NEAR(q.x, p.x, 1e-12);
  EXPECT_NEAR(q.y, p.y, 1e-12);
  const slam::Pose2 r = integrate_arc({0, 0, 0}, 0.4, 0.2, M_PI / 2 / 0.2);
  EXPECT_NEAR(r.x, 2.0, 1e-12);
  EXPECT_NEAR(r.y, 2.0, 1e-12);
  EXPECT_NEAR(r.theta, M_PI / 2, 1e-12);
  // Many small straight-then-turn steps (Euler) converge to the same point.
  const double dt = (M_PI / 2 / 0.2) / 100000;
  slam::Pose2 e{0, 0, 0};
  for (int k = 0; k < 100000; ++k) {
    e = integrate_arc(e, 0.4, 0.0, dt);
    e.theta += 0.2 * dt;
  }
  EXPECT_NEAR(e.x, 2.0, 1e-3);
  EXPECT_NEAR(e.y, 2.0, 1e-3);
}

TEST(Robot, DiscCollisionIsExact) {
  World w(40, 40, 0.05, {0.0, 0.0}, World::kFree);
  w.set({20, 20}, World::kOccupied);  // square [1.0, 1.05]^2
  EXPECT_TRUE(disc_collides(w, {0.76, 1.02}, 0.25));
  EXPECT_FALSE(disc_collides(w, {0.74, 1.02}, 0.25));
  // Diagonal: corner (1.0, 1.0) at distance 0.25 * 1.01 is clear.
  const double d = 0.25 * 1.01 / std::sqrt(2.0);
  EXPECT_FALSE(disc_collides(w, {1.0 - d, 1.0 - d}, 0.25));
  EXPECT_TRUE(disc_collides(w, {0.1, 1.0}, 0.25));  // outside the raster counts as occupied
  EXPECT_THROW(Robot(w, {1.0, 1.0, 0.0}), std::invalid_argument);
}

TEST(OdometryModel, IncrementNoiseMatchesTheMotionModel) {
  OdometryNoiseOptions o;
  o.seed = 7;
  OdometryModel odom({0, 0, 0}, o);
  const slam::Pose2 u{0.02, 0.0, 0.01};  // one 10 Hz step at 0.2 m/s, 0.1 rad/s
  const Eigen::Vector3d sigma = odom.sigmas(u);
  EXPECT_NEAR(sigma.x(), 0.1 * 0.02 + 0.1 * 0.01, 1e-15);
  EXPECT_NEAR(sigma.y(), 0.1 * 0.01 + 0.03 * 0.02, 1e-15);
  EXPECT_NEAR(sigma.z(), 0.2 * 0.01 + 0.2 * 0.02, 1e-15);
  const int n = 20000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  slam::Pose2 before = odom.pose();
  for (int k = 0; k < n; ++k) {
    const slam::Pose2 after = odom.update(u);
    const slam::Pose2 d = before.between(after);
    const Eigen::Vector3d e(d.x - u.x, d.y - u.y, slam::normalize_angle(d.theta - u.theta));
    sum += e;
    sum2 += e.cwiseProduct(e);
    before = after;
  }
  for (int i = 0; i < 3; ++i) {
    const double mean = sum[i] / n;
    EXPECT_NEAR(mean, 0.0, 4 * sigma[i] / std::sqrt(n));
    EXPECT_NEAR(std::sqrt(sum2[i] / n - mean * mean), sigma[i], 0.03 * sigma[i]);
  }
}

TEST(OdometryModel, StandingStillDoesNotDriftAndSeedsRepeat) {
  OdometryModel still({1, 2, 0.3});
  for (int k = 0; k < 100; ++k) still.update({0, 0, 0});
  EXPECT_DOUBLE_EQ(still.pose().x, 1.0);
  EXPECT_DOUBLE_EQ(still.pose().theta, 0.3);
  OdometryModel a({0, 0, 0}), b({0, 0, 0});
  for (int k = 0; k < 50; ++k) {
    a.update({0.05, 0, 0.02});
    b.update({0.05, 0, 0.02});
  }
  EXPECT_EQ(a.pose().x, b.pose().x);
  EXPECT_NE(a.pose().x, 2.5);
  OdometryNoiseOptions bad;
  bad.srt = -1;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::exploration
