// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/rbpf.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_world.hpp"

namespace lookahead::slam {
namespace {

// A drive around the inner box of the test room with odometry that drifts in heading.
std::vector<std::pair<Pose2, LaserScan>> drive() {
  const auto world = test::room_world();
  std::vector<std::pair<Pose2, LaserScan>> out;
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n(0.0, 1.0);
  Pose2 truth{1.5, 1.0, 0.0}, odom = truth;
  const std::vector<Pose2> legs{{7.0, 0, 0}, {0, 0, M_PI / 2}, {3.5, 0, 0}, {0, 0, M_PI / 2},
                                {6.5, 0, 0}, {0, 0, M_PI / 2}, {3.2, 0, 0}};
  double t = 0;
  for (const Pose2& leg : legs) {
    const int steps = leg.x > 0 ? static_cast<int>(leg.x / 0.1) : 10;
    for (int i = 0; i < steps; ++i) {
      const Pose2 step{leg.x / steps, 0, leg.theta / steps};
      truth = truth.compose(step);
      // Odometry: 3% scale error and a heading drift of 2 degrees per metre.
      odom = odom.compose({step.x * 1.03 + 0.002 * n(rng), 0.002 * n(rng), step.theta * 1.02 + step.x * 0.035});
      out.push_back({truth, test::simulate_scan(world, truth, odom, t += 0.1)});
    }
  }
  return out;
}

RbpfOptions small(int threads) {
  RbpfOptions o;
  o.particles = 20;
  o.seed = 3;
  o.threads = threads;
  o.linear_update = 0.3;
  return o;
}

TEST(Rbpf, CorrectsDriftingOdometry) {
  const auto data = drive();
  Rbpf filter(small(1));
  for (const auto& d : data) filter.add_scan(d.second);
  const auto path = filter.best_trajectory();
  // The trajectory keeps the proposal's mean, the current pose the pose the map was built
  // with: the same mean, up to where the trajectory's last node was placed.
  EXPECT_NEAR(filter.current_pose().x, path.back().x, 0.05);
  EXPECT_NEAR(filter.current_pose().y, path.back().y, 0.05);
  EXPECT_NEAR(filter.current_pose().theta, path.back().theta, 0.02);
  const Pose2 truth = data.back().first;
  const Pose2 odom = data.back().second.odometry;
  const double odom_error = std::hypot(odom.x - truth.x, odom.y - truth.y);
  const double slam_error = std::hypot(path.back().x - truth.x, path.back().y - truth.y);
  EXPECT_GT(odom_error, 0.5);
  EXPECT_LT(slam_error, 0.1);
  EXPECT_LT(std::abs(normalize_angle(path.back().theta - truth.theta)), 0.03);
  EXPECT_GT(filter.statistics().updates, 50u);
}

// The weighted mean pose (the SegSLAM paper's Table II measure) lies among the particles:
// its position within their bounding box, its heading within their spread; with one particle
// it is that particle's pose, as current_pose() gives it.
TEST(Rbpf, MeanPoseLiesAmongTheParticles) {
  const auto data = drive();
  RbpfOptions single = small(1);
  single.particles = 1;
  Rbpf filter(small(1)), one(single);
  // Half the drive, up to a scan that updated the filter (nothing to move by odometry then).
  bool updated = false;
  for (std::size_t i = 0; i < data.size() && !(updated && i > data.size() / 2); ++i) {
    updated = filter.add_scan(data[i].second);
    one.add_scan(data[i].second);
  }
  ASSERT_TRUE(updated);
  const Pose2 mean = filter.mean_pose();
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9, spread = 0;
  for (const Particle& p : filter.particles()) {
    x0 = std::min(x0, p.pose.x), x1 = std::max(x1, p.pose.x), y0 = std::min(y0, p.pose.y), y1 = std::max(y1, p.pose.y);
    spread = std::max(spread, std::abs(normalize_angle(p.pose.theta - mean.theta)));
  }
  EXPECT_GT(x1 - x0, 0.0);  // the particles differ, so the bounds mean something
  EXPECT_GE(mean.x, x0);
  EXPECT_LE(mean.x, x1);
  EXPECT_GE(mean.y, y0);
  EXPECT_LE(mean.y, y1);
  EXPECT_LT(spread, 0.2);
  EXPECT_NEAR(one.mean_pose().x, one.current_pose().x, 1e-9);
  EXPECT_NEAR(one.mean_pose().y, one.current_pose().y, 1e-9);
  EXPECT_NEAR(normalize_angle(one.mean_pose().theta - one.current_pose().theta), 0.0, 1e-9);
}

TEST(Rbpf, SameSeedSameResultWhateverTheThreadCount) {
  const auto data = drive();
  Rbpf one(small(1)), two(small(2));
  for (const auto& d : data) {
    one.add_scan(d.second);
    two.add_scan(d.second);
  }
  const auto a = one.best_trajectory(), b = two.best_trajectory();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].x, b[i].x);
    ASSERT_EQ(a[i].y, b[i].y);
    ASSERT_EQ(a[i].theta, b[i].theta);
  }
  EXPECT_EQ(one.statistics().neff, two.statistics().neff);
}

// The motion-model proposal never runs the scan matcher (no match failures to count) and
// still corrects the drift, less tightly than the scan-matching proposal; the two differ.
TEST(Rbpf, MotionModelProposalSkipsTheScanMatcher) {
  const auto data = drive();
  RbpfOptions o = small(1);
  o.particles = 60;
  o.proposal.kind = ProposalKind::kMotionModel;
  Rbpf motion(o), matched(small(1));
  for (const auto& d : data) {
    motion.add_scan(d.second);
    matched.add_scan(d.second);
  }
  EXPECT_EQ(motion.statistics().match_failures, 0u);
  EXPECT_GT(motion.statistics().updates, 50u);
  const Pose2 truth = data.back().first, odom = data.back().second.odometry;
  const Pose2 end = motion.best_trajectory().back();
  EXPECT_LT(std::hypot(end.x - truth.x, end.y - truth.y), 0.5 * std::hypot(odom.x - truth.x, odom.y - truth.y));
  const Pose2 other = matched.best_trajectory().back();
  EXPECT_NE(end.x, other.x);
}

TEST(Rbpf, WaitsForTheMotionThreshold) {
  Rbpf filter(small(1));
  const auto world = test::room_world();
  const Pose2 p{2, 1, 0};
  EXPECT_TRUE(filter.add_scan(test::simulate_scan(world, p, p)));
  EXPECT_FALSE(filter.add_scan(test::simulate_scan(world, p, {2.1, 1, 0})));
  EXPECT_TRUE(filter.add_scan(test::simulate_scan(world, p, {2.4, 1, 0})));
  EXPECT_EQ(filter.best_trajectory().size(), 3u);
}

TEST(Rbpf, RejectsImpossibleOptions) {
  RbpfOptions o;
  o.particles = 0;
  EXPECT_THROW(Rbpf{o}, std::invalid_argument);
  o = {};
  o.resample_threshold = 1.5;
  EXPECT_THROW(Rbpf{o}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam
