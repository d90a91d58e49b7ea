// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/binned_icp.hpp"

#include <gtest/gtest.h>

#include <random>

namespace lookahead::slam::segslam {
namespace {

// Walls of a room corner with a pillar, densely sampled with noise, in the target frame.
Points2 room_points(std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, 0.005);
  Points2 p;
  for (double t = 0; t < 6; t += 0.01) p.emplace_back(t, noise(rng));
  for (double t = 0; t < 4; t += 0.01) p.emplace_back(noise(rng), t);
  for (double t = 0; t < 0.5; t += 0.01) p.emplace_back(3 + t, 2 + noise(rng)), p.emplace_back(3 + noise(rng), 2 + t);
  return p;
}

Points2 transformed(const Points2& pts, const Pose2& t) {
  Points2 out;
  for (const auto& q : pts) {
    const Pose2 w = t.compose({q.x(), q.y(), 0});
    out.emplace_back(w.x, w.y);
  }
  return out;
}

TEST(BinnedIcp, RecoversAKnownTransform) {
  std::mt19937_64 rng(3);
  const Points2 target = bin_points(room_points(rng), 0.1);
  const Pose2 truth{0.3, -0.2, 0.08};  // source -> target
  const Points2 source = bin_points(transformed(room_points(rng), truth.inverse()), 0.1);
  // From a guess inside the basin (matching seeds ICP with a coarse search), with the
  // iterations point-to-point ICP needs to creep along walls.
  const IcpResult r = icp_binned(source, target, Pose2{0.2, -0.1, 0.04}, {300, 0.5, 0.1});
  EXPECT_NEAR(r.transform.x, truth.x, 0.02);
  EXPECT_NEAR(r.transform.y, truth.y, 0.02);
  EXPECT_NEAR(r.transform.theta, truth.theta, 0.005);
  EXPECT_GT(r.inlier_ratio, 0.9);
  EXPECT_LT(r.mean_error, 0.05);
}

TEST(BinnedIcp, BinningKeepsOnePointPerBin) {
  const Points2 dense{{0.01, 0.01}, {0.02, 0.03}, {0.04, 0.02}, {0.51, 0.5}};
  const Points2 b = bin_points(dense, 0.1);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b[0].x(), (0.01 + 0.02 + 0.04) / 3, 1e-12);  // the centroid
}

TEST(BinnedIcp, FarSourceHasNoInliers) {
  std::mt19937_64 rng(3);
  const Points2 target = bin_points(room_points(rng), 0.1);
  const IcpResult r = icp_binned(transformed(target, {50, 50, 0}), target, Pose2{}, {});
  EXPECT_EQ(r.inlier_ratio, 0.0);
}

}  // namespace
}  // namespace lookahead::slam::segslam
