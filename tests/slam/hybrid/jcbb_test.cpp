// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/jcbb.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "lookahead/slam/hybrid/global_map.hpp"

namespace lookahead::slam::hybrid {
namespace {

// Two mapped features 1 m apart, known well; two new features that share a large common
// offset (their relative position is precise). Individually each new feature is compatible
// with both mapped ones, and nearest neighbour pairs both with the second; only the
// joint test sees that the pair must keep its 1 m spacing.
TEST(Jcbb, ResolvesAnAmbiguityNearestNeighbourGetsWrong) {
  // State: [b1 (2), b2 (2), a1 (2), a2 (2)].
  Eigen::VectorXd x(8);
  x << 0.0, 0.0, 1.0, 0.0, 0.6, 0.0, 1.6, 0.0;
  Eigen::MatrixXd p = 1e-4 * Eigen::MatrixXd::Identity(8, 8);
  // a1 and a2 share an x offset of variance 1 (correlation ~1).
  p(4, 4) = p(6, 6) = p(4, 6) = p(6, 4) = 1.0;
  p(4, 4) += 1e-4;
  p(6, 6) += 1e-4;
  std::vector<PairingCandidate> c;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      PairingCandidate k{i, j, x.segment<2>(4 + 2 * i) - x.segment<2>(2 * j), Eigen::MatrixXd::Zero(2, 8),
                         Eigen::Matrix2d::Zero()};
      k.jacobian.block<2, 2>(0, 4 + 2 * i).setIdentity();
      k.jacobian.block<2, 2>(0, 2 * j) = -Eigen::Matrix2d::Identity();
      const Eigen::Matrix2d s = k.jacobian * p * k.jacobian.transpose();
      ASSERT_LT(k.nu.dot(s.inverse() * k.nu), chi2_quantile(2, 0.99)) << "every pair individually compatible";
      c.push_back(k);
    }
  }
  const JcbbResult r = jcbb(2, c, p, 0.99, 1000);
  ASSERT_EQ(r.pairings, 2);
  EXPECT_EQ(r.target_of[0], 0);
  EXPECT_EQ(r.target_of[1], 1);
  EXPECT_FALSE(r.search_truncated);
}

TEST(Jcbb, LeavesAnItemUnpairedWhenNoJointHypothesisFits) {
  Eigen::VectorXd x(4);
  x << 0.0, 0.0, 0.0, 5.0;  // b at the origin, a 5 m away with 0.1 m std
  Eigen::MatrixXd p = 0.01 * Eigen::MatrixXd::Identity(4, 4);
  PairingCandidate k{0, 0, x.segment<2>(2) - x.segment<2>(0), Eigen::MatrixXd::Zero(2, 4), Eigen::Matrix2d::Zero()};
  k.jacobian.block<2, 2>(0, 2).setIdentity();
  k.jacobian.block<2, 2>(0, 0) = -Eigen::Matrix2d::Identity();
  const JcbbResult r = jcbb(1, {k}, p, 0.99, 1000);
  EXPECT_EQ(r.pairings, 0);
  EXPECT_EQ(r.target_of[0], -1);
}

TEST(Jcbb, ChiSquareQuantileIsClose) {
  EXPECT_NEAR(chi2_quantile(2, 0.99), 9.21, 0.15);
  EXPECT_NEAR(chi2_quantile(4, 0.95), 9.49, 0.1);
  EXPECT_NEAR(chi2_quantile(10, 0.99), 23.21, 0.2);
}

// The same ambiguity at fusion, through the global map: the local map's two features are
// fused with the right global ones.
TEST(GlobalMapFusion, JointCompatibilityPicksTheConsistentPairs) {
  FusionOptions o;
  GlobalMap g(o);
  GaussianMap first;
  first.mean = Eigen::VectorXd(7);
  first.mean << 10.0, 0.0, 0.0, 5.0, 2.0, 6.0, 2.0;  // vehicle, features at (5,2), (6,2)
  first.covariance = 1e-4 * Eigen::MatrixXd::Identity(7, 7);
  first.ids = {0, 1};
  first.existence = {1, 1};
  g.fuse(first);
  ASSERT_EQ(g.features(), 2u);
  // Second local map from the vehicle at (10, 0): features seen at (-4.4, 2) and (-3.4, 2)
  // (i.e. 0.6 m off in x together, with the vehicle), with a shared x uncertainty of 1 m^2.
  GaussianMap second;
  second.mean = Eigen::VectorXd(7);
  second.mean << 0.0, 0.0, 0.0, -4.4, 2.0, -3.4, 2.0;
  second.covariance = 1e-4 * Eigen::MatrixXd::Identity(7, 7);
  for (int i : {0, 3, 5}) {
    for (int j : {0, 3, 5}) second.covariance(i, j) += 1.0;  // vehicle and features offset together
  }
  second.ids = {0, 1};
  second.existence = {1, 1};
  const FusionReport r = g.fuse(second);
  EXPECT_EQ(r.associated, 2);
  ASSERT_EQ(g.features(), 2u);
  EXPECT_NEAR(g.feature(0).x(), 5.0, 0.05);
  EXPECT_NEAR(g.feature(1).x(), 6.0, 0.05);
  // Fusing pulled the new vehicle pose back by the 0.6 m the features were off.
  EXPECT_NEAR(g.origin().x, 9.4, 0.05);
}

}  // namespace
}  // namespace lookahead::slam::hybrid
