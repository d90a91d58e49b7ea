// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/global_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lookahead/slam/hybrid/motion_step.hpp"

namespace lookahead::slam::hybrid {
namespace {

// The Jacobians of g (sec. 4) against central differences, at random origins and states.
TEST(GlobalMapAugmentation, JacobiansOfGMatchNumericalDifferentiation) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Pose2 origin{u(rng), u(rng), normalize_angle(u(rng))};
    Eigen::VectorXd local(7);
    for (int i = 0; i < 7; ++i) local(i) = u(rng);
    local(2) = normalize_angle(local(2));
    const LocalToGlobal g = local_to_global(origin, local);
    constexpr double h = 1e-6;
    for (int k = 0; k < 3; ++k) {
      Pose2 plus = origin, minus = origin;
      (k == 0 ? plus.x : k == 1 ? plus.y : plus.theta) += h;
      (k == 0 ? minus.x : k == 1 ? minus.y : minus.theta) -= h;
      Eigen::VectorXd d = (local_to_global(plus, local).value - local_to_global(minus, local).value) / (2 * h);
      d(2) = normalize_angle(d(2) * 2 * h) / (2 * h);
      EXPECT_LT((d - g.d_origin.col(k)).cwiseAbs().maxCoeff(), 1e-6) << "origin column " << k;
    }
    for (int k = 0; k < 7; ++k) {
      Eigen::VectorXd plus = local, minus = local;
      plus(k) += h;
      minus(k) -= h;
      Eigen::VectorXd d = (local_to_global(origin, plus).value - local_to_global(origin, minus).value) / (2 * h);
      d(2) = normalize_angle(d(2) * 2 * h) / (2 * h);
      EXPECT_LT((d - g.d_local.col(k)).cwiseAbs().maxCoeff(), 1e-6) << "local column " << k;
    }
  }
}

// Augmentation adds the local map with the covariance of sec. 4: cross terms dg_v P_v:, and
// the new block dg_v P_vv dg_v^T + dg_z P_L dg_z^T.
TEST(GlobalMapAugmentation, CovarianceFollowsThePaper) {
  FusionOptions o;
  GlobalMap g(o, {1.0, 2.0, 0.5});
  GaussianMap first;  // gives the origin some uncertainty first
  first.mean = Eigen::Vector3d(3.0, 0.0, 0.2);
  first.covariance = Eigen::Matrix3d::Identity() * 0.04;
  g.fuse(first);
  const Eigen::MatrixXd p0 = g.covariance();
  const Pose2 v = g.origin();
  GaussianMap local;
  local.mean = Eigen::VectorXd(5);
  local.mean << 1.0, 1.0, 0.1, 4.0, -2.0;
  local.covariance = Eigen::MatrixXd::Identity(5, 5) * 0.01;
  local.ids = {0};
  local.existence = {1.0};
  g.augment(local);
  const LocalToGlobal lg = local_to_global(v, local.mean);
  const Eigen::MatrixXd expected_new =
      lg.d_origin * p0 * lg.d_origin.transpose() + lg.d_local * local.covariance * lg.d_local.transpose();
  EXPECT_LT((g.covariance().bottomRightCorner(5, 5) - expected_new).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((g.covariance().bottomLeftCorner(5, 3) - lg.d_origin * p0).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((g.mean().tail(5) - lg.value).cwiseAbs().maxCoeff(), 1e-12);
}

// A fusion corrects the new vehicle pose (the next origin) through a re-observed feature; the
// next augmentation linearises g at that corrected origin, not at the value it was augmented with.
GaussianMap local_map(const Eigen::Vector3d& vehicle, const Eigen::Vector2d& feature) {
  GaussianMap m;
  m.mean = Eigen::VectorXd(5);
  m.mean << vehicle, feature;
  m.covariance = Eigen::MatrixXd::Identity(5, 5) * 0.01;
  m.covariance(2, 2) = 0.003;
  m.ids = {0};
  m.existence = {1.0};
  return m;
}

TEST(GlobalMapAugmentation, LinearisesAtTheCorrectedOrigin) {
  {
    FusionOptions o;
    GlobalMap g(o, {1.0, 2.0, 0.5});
    g.fuse(local_map({3.0, 0.0, 0.2}, {5.0, 2.0}));
    ASSERT_EQ(g.features(), 1u);
    // The feature seen again from the new origin, 12 cm off: it associates, and the
    // zero-noise fusion moves the new vehicle pose.
    const Pose2 v1 = g.origin();
    const Pose2 f = v1.inverse().compose({g.feature(0).x(), g.feature(0).y(), 0.0});
    const GaussianMap second = local_map({2.0, 0.5, 0.1}, {f.x + 0.1, f.y - 0.07});
    const Pose2 augmented = to_pose(local_to_global(v1, second.mean).value.head<3>());
    ASSERT_EQ(g.fuse(second).associated, 1);
    ASSERT_GT(std::abs(normalize_angle(g.origin().theta - augmented.theta)), 1e-3) << "the fusion must move the origin";
    const Pose2 expected = g.origin();

    const Eigen::MatrixXd p0 = g.covariance();
    const GaussianMap third = local_map({1.0, 1.0, 0.1}, {4.0, -2.0});
    g.augment(third);
    const LocalToGlobal at_expected = local_to_global(expected, third.mean);
    const LocalToGlobal at_other = local_to_global(augmented, third.mean);
    const Eigen::MatrixXd cross = g.covariance().bottomLeftCorner(5, p0.cols());
    EXPECT_LT((cross - at_expected.d_origin * p0.topRows(3)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT((cross - at_other.d_origin * p0.topRows(3)).cwiseAbs().maxCoeff(), 1e-4);
    // The mean is still g at the current estimate.
    EXPECT_LT((g.mean().tail(5) - local_to_global(g.origin(), third.mean).value).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// Eq. (10): after the zero-noise difference observation the two copies are one feature,
// more certain than either.
TEST(GlobalMapFusion, ZeroNoiseDifferenceMergesTwoCopies) {
  FusionOptions o;
  GlobalMap g(o);
  GaussianMap a;
  a.mean = Eigen::VectorXd(5);
  a.mean << 0.0, 0.0, 0.0, 5.0, 0.0;
  a.covariance = Eigen::MatrixXd::Identity(5, 5) * 0.01;
  a.covariance(0, 0) = a.covariance(1, 1) = a.covariance(2, 2) = 0.0;
  a.ids = {0};
  a.existence = {1.0};
  g.fuse(a);
  GaussianMap b = a;
  b.mean(3) = 5.1;  // seen again from the same spot, slightly elsewhere
  g.fuse(b);
  ASSERT_EQ(g.features(), 1u);
  EXPECT_NEAR(g.feature(0).x(), 5.05, 1e-9);
  EXPECT_NEAR(g.feature_covariance(0)(0, 0), 0.005, 1e-9);
}

}  // namespace
}  // namespace lookahead::slam::hybrid
