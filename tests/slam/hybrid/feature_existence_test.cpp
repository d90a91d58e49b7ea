// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/feature_existence.hpp"

#include <gtest/gtest.h>

#include "correspondence_vote.hpp"

namespace lookahead::slam::hybrid {
namespace {

TEST(FeatureExistence, DetectionFollowsEquation11) {
  ExistenceOptions o;
  o.alpha = 0.7;
  o.beta = 0.04;
  const FeatureExistence e(o);
  EXPECT_NEAR(e.detected(0.5), 0.5 * 0.7 / (0.5 * 0.7 + 0.5 * 0.04), 1e-12);
  EXPECT_NEAR(e.missed(0.5), 0.5 * 0.3 / (0.5 * 0.3 + 0.5 * 0.96), 1e-12);
  // Clutter seen once and then missed in view fades; a feature seen often stays.
  double clutter = e.created(), feature = e.created();
  for (int i = 0; i < 10; ++i) clutter = e.missed(clutter);
  for (int i = 0; i < 10; ++i) feature = (i % 3 == 2) ? e.missed(feature) : e.detected(feature);
  EXPECT_LT(clutter, 0.01);
  EXPECT_GT(feature, 0.99);
}

TEST(FeatureExistence, ClampKeepsTheCleanSensorFinite) {
  ExistenceOptions o;  // alpha = 1, beta = 0: clamped to 0.98 / 0.02
  const FeatureExistence e(o);
  EXPECT_GT(e.missed(0.99), 0.0);
  EXPECT_LT(e.detected(0.5), 1.0);
  o.alpha = 1.5;
  EXPECT_THROW(FeatureExistence{o}, std::invalid_argument);
}

// Sec. 3.1: the weighted majority wins and every particle's landmark takes its gamma.
TEST(CorrespondenceVote, WeightedMajorityOverwritesGamma) {
  std::vector<Particle> p(3);
  for (auto& q : p)
    q.landmarks = {{{0, 0}, Eigen::Matrix2d::Identity(), 0.9, 5}, {{1, 0}, Eigen::Matrix2d::Identity(), 0.9, 6}};
  p[0].weight = 0.5;  // associates with its landmark 0 (gamma 5)
  p[1].weight = 0.3;  // associates with its landmark 1 (gamma 6)
  p[2].weight = 0.2;  // creates a landmark
  p[2].landmarks.push_back({{2, 0}, Eigen::Matrix2d::Identity(), 0.5, -1});
  std::vector<std::vector<Decision>> d = {
      {{Decision::Kind::kAssociated, 0}}, {{Decision::Kind::kAssociated, 1}}, {{Decision::Kind::kCreated, 2}}};
  long next = 100;
  const std::vector<long> won = vote_correspondences(p, d, next);
  ASSERT_EQ(won.size(), 1u);
  EXPECT_EQ(won[0], 5);
  EXPECT_EQ(p[1].landmarks[1].id, 5);  // overwritten: the minority now agrees
  EXPECT_EQ(p[2].landmarks[2].id, 5);
  EXPECT_EQ(next, 100);  // no new identity was needed
  // With the weights turned around, "new" wins and all three share a fresh identity.
  p[0].weight = 0.2, p[2].weight = 0.5;
  vote_correspondences(p, d, next);
  EXPECT_EQ(p[0].landmarks[0].id, 100);
  EXPECT_EQ(p[2].landmarks[2].id, 100);
}

}  // namespace
}  // namespace lookahead::slam::hybrid
