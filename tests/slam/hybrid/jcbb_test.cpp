// SPDX-License-Identifier: MIT
#include "jcbb.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

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
  EXPECT_NEAR(chi2_quantile(2, 0.99), 9.2103, 1e-4);  // tables
  EXPECT_NEAR(chi2_quantile(4, 0.95), 9.4877, 1e-4);
  EXPECT_NEAR(chi2_quantile(10, 0.99), 23.2093, 1e-4);
  EXPECT_NEAR(chi2_quantile(2, 0.99), -2 * std::log(0.01), 1e-9);  // 2 dof: exponential
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

namespace lookahead::slam::hybrid {
namespace {

// Reference: the search before the NIS bound (kept here to compare with): branch on
// jointly compatible pairings, cut only by the pairing count, explore every tie.
struct TieExploringSearch {
  int items;
  const std::vector<PairingCandidate>& c;
  const Eigen::MatrixXd& p;
  int best = 0, nodes = 0;
  double best_nis = 0.0;
  std::vector<int> target_of;

  double nis(const std::vector<std::size_t>& chosen) const {
    const Eigen::Index m = 2 * static_cast<Eigen::Index>(chosen.size());
    Eigen::VectorXd nu(m);
    Eigen::MatrixXd h(m, p.cols());
    for (std::size_t k = 0; k < chosen.size(); ++k) {
      nu.segment<2>(2 * static_cast<Eigen::Index>(k)) = c[chosen[k]].nu;
      h.middleRows(2 * static_cast<Eigen::Index>(k), 2) = c[chosen[k]].jacobian;
    }
    const double d = nu.dot((h * p * h.transpose()).ldlt().solve(nu));
    return d <= chi2_quantile(static_cast<int>(m), 0.99) ? d : INFINITY;
  }
  void run(int item, std::vector<std::size_t>& chosen) {
    ++nodes;
    const int have = static_cast<int>(chosen.size());
    if (item == items) {
      const double d = have == 0 ? 0.0 : nis(chosen);
      if (have > best || (have == best && d < best_nis)) {
        best = have, best_nis = d;
        target_of.assign(static_cast<std::size_t>(items), -1);
        for (std::size_t k : chosen) target_of[static_cast<std::size_t>(c[k].item)] = c[k].target;
      }
      return;
    }
    for (std::size_t k = 0; k < c.size(); ++k) {
      if (c[k].item != item) continue;
      bool taken = false;
      for (std::size_t q : chosen) taken = taken || c[q].target == c[k].target;
      if (taken) continue;
      chosen.push_back(k);
      if (std::isfinite(nis(chosen))) run(item + 1, chosen);
      chosen.pop_back();
    }
    if (have + (items - item - 1) >= best) run(item + 1, chosen);
  }
};

// A dense map: each of 6 observed features has its true mapped feature 1 cm off and a
// second one 0.25 m off (0.1 m std: individually compatible, NIS ~6). Up to four wrong
// pairings still pass the joint test, so dozens of complete hypotheses tie on the pairing
// count; once the all-true one is found, the NIS bound cuts every branch that takes a
// wrong pairing. Same optimum as the tie-exploring search, far fewer nodes.
TEST(Jcbb, NisBoundKeepsTheExhaustiveOptimumInADenseCluster) {
  const int n = 6, mapped = 2 * n;
  const int size = 2 * (mapped + n), obs = 2 * mapped;  // state: mapped, then observed
  Eigen::VectorXd x(size);
  Eigen::MatrixXd p = 1e-4 * Eigen::MatrixXd::Identity(size, size);
  for (int i = 0; i < n; ++i) {
    x.segment<2>(2 * (2 * i)) << 5.0 * i, 0.0;             // true target
    x.segment<2>(2 * (2 * i + 1)) << 5.0 * i + 0.26, 0.0;  // near neighbour
    x.segment<2>(obs + 2 * i) << 5.0 * i + 0.01, 0.0;
    p.block<2, 2>(obs + 2 * i, obs + 2 * i) = 0.01 * Eigen::Matrix2d::Identity();
  }
  std::vector<PairingCandidate> c;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < mapped; ++j) {
      PairingCandidate k{i, j, x.segment<2>(obs + 2 * i) - x.segment<2>(2 * j), Eigen::MatrixXd::Zero(2, size),
                         Eigen::Matrix2d::Zero()};
      k.jacobian.block<2, 2>(0, obs + 2 * i).setIdentity();
      k.jacobian.block<2, 2>(0, 2 * j) = -Eigen::Matrix2d::Identity();
      const Eigen::Matrix2d s = k.jacobian * p * k.jacobian.transpose();
      if (k.nu.dot(s.inverse() * k.nu) < chi2_quantile(2, 0.99)) c.push_back(k);
    }
  }
  ASSERT_EQ(c.size(), static_cast<std::size_t>(2 * n)) << "two individually compatible targets per observation";
  TieExploringSearch reference{n, c, p};
  std::vector<std::size_t> chosen;
  reference.run(0, chosen);
  const JcbbResult r = jcbb(n, c, p, 0.99, 1000000);
  EXPECT_FALSE(r.search_truncated);
  EXPECT_EQ(r.pairings, n);
  EXPECT_EQ(r.pairings, reference.best);
  EXPECT_EQ(r.target_of, reference.target_of);
  for (int i = 0; i < n; ++i) EXPECT_EQ(r.target_of[static_cast<std::size_t>(i)], 2 * i);
  EXPECT_NEAR(r.nis, reference.best_nis, 1e-9 * std::max(1.0, reference.best_nis));
  EXPECT_LT(3 * r.nodes, reference.nodes) << "the NIS bound should cut the tied wrong hypotheses";
}

}  // namespace
}  // namespace lookahead::slam::hybrid
