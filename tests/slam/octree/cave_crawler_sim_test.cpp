// SPDX-License-Identifier: MIT
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

#include <gtest/gtest.h>

#include "lookahead/slam/sim3d/octree_ray_cast.hpp"

namespace lookahead::slam {
namespace {

// The garage with a short route: the first 12 m of the loop.
World3 short_garage(std::uint64_t seed) {
  World3 w = make_garage_world(seed, 0.2);
  w.route.resize(2);
  return w;
}

TEST(GarageWorld, HasTwoDecksAndAClosedLoop) {
  const World3 w = make_garage_world(1);
  const Eigen::Vector3d up(0, 0, 1);
  // From the start, the ground floor is below and the upper deck above at 3.3 m.
  const Eigen::Vector3d start = w.route.front() + Eigen::Vector3d(0, 0, 0.6);
  EXPECT_NEAR(*cast_ray(w.map, start, -up, 10.0), 0.6, 0.11);
  EXPECT_NEAR(*cast_ray(w.map, start, up, 10.0), 3.3 - 0.2 - 0.6, 0.11);
  double length = 0;
  for (std::size_t i = 1; i < w.route.size(); ++i) length += (w.route[i] - w.route[i - 1]).norm();
  EXPECT_NEAR(length, 290.0, 10.0);
  EXPECT_LT((w.route.back() - w.route.front()).norm(), 1.0);
  // Every leg of the route is clear at the laser's height.
  for (std::size_t i = 1; i < w.route.size(); ++i) {
    const Eigen::Vector3d a = w.route[i - 1] + Eigen::Vector3d(0, 0, 0.6);
    const Eigen::Vector3d d = w.route[i] - w.route[i - 1];
    EXPECT_FALSE(cast_ray(w.map, a, d.normalized(), d.norm())) << "leg " << i << " is blocked";
  }
}

TEST(GarageWorld, SameSeedSameCars) {
  EXPECT_EQ(make_garage_world(5, 0.2).map.known_voxels(), make_garage_world(5, 0.2).map.known_voxels());
  EXPECT_NE(make_garage_world(5, 0.2).map.known_voxels(), make_garage_world(6, 0.2).map.known_voxels());
}

TEST(CaveCrawlerSim, SameSeedSameLogOtherSeedOtherNoise) {
  const World3 w = short_garage(1);
  const RangeLog3 a = simulate_cave_crawler(w, {}, 7), b = simulate_cave_crawler(w, {}, 7),
                  c = simulate_cave_crawler(w, {}, 8);
  ASSERT_EQ(a.sweeps.size(), b.sweeps.size());
  ASSERT_GE(a.sweeps.size(), 10U);
  for (std::size_t i = 0; i < a.sweeps.size(); ++i) {
    ASSERT_EQ(a.sweeps[i].rays.size(), 30U * 61U);
    EXPECT_TRUE(a.sweeps[i].odometry.isApprox(b.sweeps[i].odometry));
    for (std::size_t k = 0; k < a.sweeps[i].rays.size(); k += 97) {
      EXPECT_EQ(a.sweeps[i].rays[k].end, b.sweeps[i].rays[k].end);
    }
  }
  EXPECT_NE(a.sweeps.back().rays[5].end, c.sweeps.back().rays[5].end);
}

TEST(CaveCrawlerSim, TruthIsOnTheRouteAndDeadReckoningDriftsWithTheYawBias) {
  CaveCrawlerOptions o;
  o.dead_reckoning = {0.0, 0.0, 0.01, 0.0, 0.0};  // a pure yaw bias of 0.01 rad/s
  const World3 w = short_garage(1);
  const RangeLog3 log = simulate_cave_crawler(w, o, 1);
  const Pose3& truth = *log.sweeps.back().truth;
  EXPECT_NEAR(truth.translation().y(), 7.0, 1e-9);
  const double yaw_error = euler_of(log.sweeps.back().odometry.linear()).yaw - euler_of(truth.linear()).yaw;
  EXPECT_NEAR(yaw_error, 0.01 * log.sweeps.back().time, 1e-6);
}

}  // namespace
}  // namespace lookahead::slam
