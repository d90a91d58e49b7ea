// SPDX-License-Identifier: MIT
#include "moment_matching.hpp"

#include <gtest/gtest.h>

namespace lookahead::slam::hybrid {
namespace {

Landmark landmark(double x, double y, double var, long id, double existence = 1.0) {
  return {{x, y}, var * Eigen::Matrix2d::Identity(), existence, id};
}

// Two particles, weights 1/4 and 3/4, one common feature (id 7). By hand (eq. 6-7):
//   vehicle mean = 0.25 (0, 0, 0) + 0.75 (2, 0, 0.4) = (1.5, 0, 0.3)
//   vehicle cov  = 0.25 d1 d1^T + 0.75 d2 d2^T, d1 = (-1.5, 0, -0.3), d2 = (0.5, 0, 0.1):
//                  xx = 0.25 * 2.25 + 0.75 * 0.25 = 0.75; x-theta = 0.25 * 0.45 + 0.75 * 0.05 = 0.15
//   feature mean = 0.25 (10, 0) + 0.75 (10, 4) = (10, 3)
//   feature cov  = 0.25 * 0.1 I + 0.75 * 0.3 I + spread: yy = 0.25 * 9 + 0.75 * 1 = 3
//   vehicle x / feature y = 0.25 (-1.5)(-3) + 0.75 (0.5)(1) = 1.5
TEST(MomentMatching, MatchesAHandComputedMixture) {
  std::vector<Particle> p(2);
  p[0] = {{0.0, 0.0, 0.0}, 0.25, {landmark(10, 0, 0.1, 7)}};
  p[1] = {{2.0, 0.0, 0.4}, 0.75, {landmark(10, 4, 0.3, 7)}};
  std::mt19937_64 rng(1);
  const GaussianMap g = moment_match(p, 0.5, rng);
  ASSERT_EQ(g.features(), 1u);
  EXPECT_EQ(g.ids[0], 7);
  EXPECT_NEAR(g.mean(0), 1.5, 1e-12);
  EXPECT_NEAR(g.mean(2), 0.3, 1e-12);
  EXPECT_NEAR(g.mean(3), 10.0, 1e-12);
  EXPECT_NEAR(g.mean(4), 3.0, 1e-12);
  EXPECT_NEAR(g.covariance(0, 0), 0.75, 1e-12);
  EXPECT_NEAR(g.covariance(0, 2), 0.15, 1e-12);
  EXPECT_NEAR(g.covariance(1, 1), 0.0, 1e-12);  // particles have no vehicle covariance
  EXPECT_NEAR(g.covariance(3, 3), 0.25 * 0.1 + 0.75 * 0.3, 1e-12);
  EXPECT_NEAR(g.covariance(4, 4), 0.25 * 0.1 + 0.75 * 0.3 + 3.0, 1e-12);
  EXPECT_NEAR(g.covariance(0, 4), 1.5, 1e-12);
  EXPECT_NEAR(g.covariance(4, 0), 1.5, 1e-12);
  EXPECT_NEAR(g.existence[0], 1.0, 1e-12);
}

// Sec. 3.2, second corner case: a particle without the feature is ignored for it.
TEST(MomentMatching, ParticleWithoutTheFeatureIsIgnoredForIt) {
  std::vector<Particle> p(2);
  p[0] = {{0.0, 0.0, 0.0}, 0.5, {landmark(5, 5, 0.2, 3)}};
  p[1] = {{1.0, 0.0, 0.0}, 0.5, {}};
  std::mt19937_64 rng(1);
  const GaussianMap g = moment_match(p, 0.1, rng);
  ASSERT_EQ(g.features(), 1u);
  EXPECT_NEAR(g.mean(3), 5.0, 1e-12);  // not pulled towards anything by particle 1
  EXPECT_NEAR(g.mean(4), 5.0, 1e-12);
  EXPECT_NEAR(g.existence[0], 0.5, 1e-12);  // existence counts the absent particle as 0
  EXPECT_NEAR(g.mean(0), 0.5, 1e-12);
  EXPECT_NEAR(g.covariance(3, 3), 0.2, 1e-12);
  // A feature held by too little weight is left out.
  EXPECT_EQ(moment_match(p, 0.6, rng).features(), 0u);
}

// Sec. 3.2, first corner case: duplicates of one gamma in a particle; one is chosen at random.
TEST(MomentMatching, DuplicateCorrespondenceUsesOneOfTheCopies) {
  std::vector<Particle> p(1);
  p[0] = {{0.0, 0.0, 0.0}, 1.0, {landmark(1, 0, 0.1, 4), landmark(3, 0, 0.1, 4)}};
  int first = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    std::mt19937_64 rng(seed);
    const GaussianMap g = moment_match(p, 0.5, rng);
    ASSERT_EQ(g.features(), 1u);
    ASSERT_TRUE(g.mean(3) == 1.0 || g.mean(3) == 3.0) << g.mean(3);  // a copy, never the average
    first += g.mean(3) == 1.0;
  }
  EXPECT_GT(first, 5);
  EXPECT_LT(first, 35);
}

TEST(MomentMatching, HeadingsAcrossPiAverageToPi) {
  std::vector<Particle> p(2);
  p[0] = {{0.0, 0.0, M_PI - 0.1}, 0.5, {}};
  p[1] = {{0.0, 0.0, -M_PI + 0.1}, 0.5, {}};
  const PoseGaussian g = moment_match_pose(p);
  EXPECT_NEAR(std::abs(g.mean.theta), M_PI, 1e-9);
  EXPECT_NEAR(g.covariance(2, 2), 0.01, 1e-9);
}

}  // namespace
}  // namespace lookahead::slam::hybrid
