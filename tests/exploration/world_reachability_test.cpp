// SPDX-License-Identifier: MIT
// The reachable free area, the denominator of every coverage figure: a door is open to the
// count exactly when the robot's disc passes it (Robot::step's collision check).
#include "lookahead/exploration/world_reachability.hpp"

#include <gtest/gtest.h>

#include <random>

#include "lookahead/exploration/robot.hpp"

namespace lookahead::exploration {
namespace {

TEST(WorldReachability, WideDiscCannotPassANarrowGap) {
  // Two 2 m rooms joined by a 0.4 m gap: a point passes, a 0.25 m disc does not.
  World w(80, 40, 0.05, {0, 0}, World::kFree);
  w.fill_rect({1.95, 0.0}, {2.05, 2.0}, World::kOccupied);
  w.fill_rect({1.95, 0.8}, {2.05, 1.2}, World::kFree);
  EXPECT_EQ(reachable_free_area(w, {1.0, 1.0}, 0.0).reachable_cells, w.free_cell_count());
  const ReachableArea disc = reachable_free_area(w, {1.0, 1.0}, 0.25);
  EXPECT_NEAR(disc.area_m2, 1.95 * 2.0, 0.1);
  EXPECT_FALSE(reachable_free_area(w, {2.0, 0.1}, 0.25).start_valid);
}

// Two 4 m x 4 m rooms at 0.2 m per pixel (as the KTH plans) behind a one-pixel wall with a
// door two pixels (0.4 m) wide.
World two_rooms_with_a_two_pixel_door() {
  World w(40, 20, 0.2, {0, 0}, World::kFree);
  w.fill_rect({3.9, 0.0}, {4.1, 4.0}, World::kOccupied);
  w.fill_rect({3.9, 1.8}, {4.1, 2.2}, World::kFree);
  return w;
}

TEST(WorldReachability, ATwoPixelDoorIsOpenToARobotThatDrivesThroughIt) {
  const World w = two_rooms_with_a_two_pixel_door();
  // The P2 robot (0.1 m radius) drives through: no pose on the line through the door collides.
  for (double x = 1.0; x <= 7.0; x += 0.01) ASSERT_FALSE(disc_collides(w, {x, 2.0}, 0.1)) << x;
  const ReachableArea a = reachable_free_area(w, {1.0, 2.0}, 0.1);
  ASSERT_TRUE(a.start_valid);
  EXPECT_EQ(a.reachable_cells, w.free_cell_count());
  EXPECT_TRUE(a.reachable[static_cast<std::size_t>(10 * w.width() + 35)]);
}

TEST(WorldReachability, ATwoPixelDoorIsShutToAWiderRobot) {
  const World w = two_rooms_with_a_two_pixel_door();
  EXPECT_TRUE(disc_collides(w, {4.0, 2.0}, 0.25));
  const ReachableArea a = reachable_free_area(w, {1.0, 2.0}, 0.25);
  ASSERT_TRUE(a.start_valid);
  EXPECT_FALSE(a.reachable[static_cast<std::size_t>(10 * w.width() + 35)]);
  EXPECT_LT(a.area_m2, 4.2 * 4.0);
}

// Property over random rooms at 0.2 m per pixel: a start the robot's disc collides at is never
// valid, and one with a sample's width of room to spare always is.
TEST(WorldReachability, StartValidityAgreesWithTheCollisionCheck) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 6.0);
  int collide = 0, clear = 0;
  for (int world = 0; world < 20; ++world) {
    World w(30, 30, 0.2, {0, 0}, World::kFree);
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector2d lo(u(rng), u(rng));
      w.fill_rect(lo, lo + Eigen::Vector2d(0.2 + u(rng) / 4, 0.2 + u(rng) / 4), World::kOccupied);
    }
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector2d p(u(rng), u(rng));
      const bool valid = reachable_free_area(w, p, 0.1).start_valid;
      if (disc_collides(w, p, 0.1)) {
        EXPECT_FALSE(valid) << p.transpose();
        ++collide;
      } else if (!disc_collides(w, p, 0.1 + 0.05 * std::sqrt(0.5))) {
        EXPECT_TRUE(valid) << p.transpose();
        ++clear;
      }
    }
  }
  EXPECT_GT(collide, 100);
  EXPECT_GT(clear, 1000);
}

}  // namespace
}  // namespace lookahead::exploration
