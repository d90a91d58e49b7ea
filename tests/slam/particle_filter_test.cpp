// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/particle_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

namespace lookahead::slam {
namespace {

struct Weighted {
  double log_weight = 0.0;
  int id = 0;
};

TEST(ParticleFilter, BestParticleIsTheFirstOfTheLargestWeights) {
  const std::vector<Weighted> p{{-3, 0}, {-1, 1}, {-2, 2}, {-1, 3}};
  EXPECT_EQ(best_particle_index(p), 1u);
  // Through a callable: the weight can be anything the particle holds.
  EXPECT_EQ(best_particle_index(p, [](const Weighted& w) { return static_cast<double>(w.id); }), 3u);
  EXPECT_EQ(best_particle_index(std::vector<Weighted>{{5, 0}}), 0u);
}

TEST(ParticleFilter, ShiftingLogWeightsKeepsTheNormalisedWeights) {
  std::vector<Weighted> p{{-1000.0, 0}, {-1000.0 + std::log(3.0), 1}};
  const std::vector<double> before = particle_weights(p);
  shift_log_weights(p);
  EXPECT_EQ(std::max(p[0].log_weight, p[1].log_weight), 0.0);
  const std::vector<double> after = particle_weights(p);
  EXPECT_NEAR(after[0], 0.25, 1e-12);
  EXPECT_EQ(before, after);
}

TEST(ParticleFilter, ResamplesOnlyBelowTheThreshold) {
  EXPECT_FALSE(should_resample(5.0, 0.5, 10));  // N_eff = N / 2 is enough
  EXPECT_TRUE(should_resample(4.99, 0.5, 10));
  EXPECT_TRUE(should_resample(std::numeric_limits<double>::quiet_NaN(), 0.5, 10));
}

TEST(ParticleFilter, EqualWeightsAreLeftAlone) {
  std::vector<Weighted> p{{-2, 0}, {-2, 1}, {-2, 2}, {-2, 3}};
  std::mt19937_64 rng(3);
  bool resampled = true;
  EXPECT_NEAR(resample_if_degenerate(p, 0.5, rng, resampled), 4.0, 1e-12);
  EXPECT_FALSE(resampled);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(p[i].id, static_cast<int>(i));
  EXPECT_EQ(p[0].log_weight, -2.0);
}

TEST(ParticleFilter, ADominantParticleTakesTheWholeSet) {
  std::vector<Weighted> p{{-500, 0}, {0, 1}, {-500, 2}, {-500, 3}};
  std::mt19937_64 rng(3);
  bool resampled = false;
  EXPECT_NEAR(resample_if_degenerate(p, 0.5, rng, resampled), 1.0, 1e-9);
  EXPECT_TRUE(resampled);
  ASSERT_EQ(p.size(), 4u);
  for (const Weighted& w : p) {
    EXPECT_EQ(w.id, 1);
    EXPECT_EQ(w.log_weight, 0.0);
  }
}

TEST(ParticleFilter, DrawResetsTheWeightOfEveryCopy) {
  std::vector<Weighted> p{{-1, 0}, {-2, 1}, {-3, 2}};
  draw_particles(p, {2, 2, 0}, [](Weighted& w) { w.log_weight = 7; });
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].id, 2);
  EXPECT_EQ(p[1].id, 2);
  EXPECT_EQ(p[2].id, 0);
  for (const Weighted& w : p) EXPECT_EQ(w.log_weight, 7.0);
}

// Headings either side of +-pi average to pi, not to 0.
TEST(ParticleFilter, MeanHeadingIsCircular) {
  const std::vector<Pose2> poses{{1, 0, M_PI - 0.1}, {3, 2, -M_PI + 0.1}};
  const Pose2 mean = weighted_mean_pose({0.5, 0.5}, [&](std::size_t i) { return poses[i]; });
  EXPECT_NEAR(mean.x, 2.0, 1e-12);
  EXPECT_NEAR(mean.y, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(mean.theta), M_PI, 1e-9);
  const Pose2 leaning = weighted_mean_pose({0.25, 0.75}, [&](std::size_t i) { return poses[i]; });
  EXPECT_NEAR(leaning.x, 2.5, 1e-12);
  EXPECT_LT(leaning.theta, 0.0);  // the heavier heading is just above -pi
}

TEST(ParticleFilter, MeanLevelPoseAndPosition) {
  const std::vector<Pose4> poses{{0, 0, 1, 0.2}, {2, 4, 3, 0.4}};
  const Pose4 mean = weighted_mean_level_pose({0.5, 0.5}, [&](std::size_t i) { return poses[i]; });
  EXPECT_NEAR(mean.x, 1.0, 1e-12);
  EXPECT_NEAR(mean.y, 2.0, 1e-12);
  EXPECT_NEAR(mean.z, 2.0, 1e-12);
  EXPECT_NEAR(mean.yaw, 0.3, 1e-12);
  const Eigen::Vector3d p =
      weighted_mean_position({0.75, 0.25}, [&](std::size_t i) -> Eigen::Vector3d { return poses[i].position(); });
  EXPECT_NEAR((p - Eigen::Vector3d(0.5, 1.0, 1.5)).norm(), 0.0, 1e-12);
}

struct Node {
  int value;
  std::shared_ptr<const Node> parent;
};

TEST(ParticleFilter, ChainIsReadOldestFirst) {
  auto a = std::make_shared<const Node>(Node{1, nullptr});
  auto b = std::make_shared<const Node>(Node{2, a});
  auto c = std::make_shared<const Node>(Node{3, b});
  const std::vector<const Node*> nodes = chain_oldest_first(c.get());
  ASSERT_EQ(nodes.size(), 3u);
  EXPECT_EQ(nodes[0]->value, 1);
  EXPECT_EQ(nodes[2]->value, 3);
  EXPECT_TRUE(chain_oldest_first<Node>(nullptr).empty());
}

// Scans between updates are carried from the latest update by the odometry between them;
// scans before the first update are placed back from it.
TEST(ParticleFilter, PosesAtEveryScanFollowTheOdometryBetweenUpdates) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  const std::vector<std::pair<std::size_t, Pose2>> updates{{1, {10, 0, M_PI / 2}}, {3, {20, 0, 0}}};
  const auto motion = [&](std::size_t from, std::size_t to) { return odometry[from].between(odometry[to]); };
  const std::vector<Pose2> out = poses_at_every_scan(updates, odometry.size(), motion);
  ASSERT_EQ(out.size(), 5u);
  EXPECT_NEAR(out[0].y, -1.0, 1e-12);  // one metre behind the first update, turned by pi/2
  EXPECT_NEAR(out[1].x, 10.0, 1e-12);
  EXPECT_NEAR(out[2].x, 10.0, 1e-12);
  EXPECT_NEAR(out[2].y, 1.0, 1e-12);
  EXPECT_NEAR(out[3].x, 20.0, 1e-12);
  EXPECT_NEAR(out[4].x, 21.0, 1e-12);
  EXPECT_TRUE(poses_at_every_scan(std::vector<std::pair<std::size_t, Pose2>>{}, 5, motion).empty());
}

}  // namespace
}  // namespace lookahead::slam
