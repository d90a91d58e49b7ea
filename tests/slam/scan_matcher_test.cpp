// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/scan_matcher.hpp"

#include <gtest/gtest.h>

#include <set>

#include "lookahead/slam/rbpf/improved_proposal.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"
#include "test_world.hpp"

namespace lookahead::slam {
namespace {

class ScanMatcherTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto world = test::room_world();
    // Map from three exact scans, then a scan from a pose the matcher must find.
    for (const Pose2& p : {Pose2{1.5, 1.0, 0.3}, Pose2{8.5, 1.5, 2.0}, Pose2{2.0, 5.0, -0.8}}) {
      insert_scan(grid, p, test::simulate_scan(world, p, p), {});
    }
    scan = prepare_scan(test::simulate_scan(world, truth, truth), LikelihoodOptions{});
  }
  OccupancyGrid grid;
  Pose2 truth{6.0, 1.2, 0.7};
  PreparedScan scan;
  LikelihoodFieldModel model{LikelihoodOptions{}, grid};
};

TEST_F(ScanMatcherTest, LikelihoodPeaksAtTheTruePose) {
  const double at_truth = model.log_likelihood(grid, truth, scan);
  EXPECT_GT(at_truth, model.log_likelihood(grid, {truth.x + 0.1, truth.y, truth.theta}, scan));
  EXPECT_GT(at_truth, model.log_likelihood(grid, {truth.x, truth.y - 0.1, truth.theta}, scan));
  EXPECT_GT(at_truth, model.log_likelihood(grid, {truth.x, truth.y, truth.theta + 0.05}, scan));
}

// The bilinear lookup reads the field between cell centres: one end point by a wall, moved a
// millimetre at a time across a cell, scores in steps of a cell with the cell lookup and
// anew at every millimetre with the bilinear one.
TEST_F(ScanMatcherTest, TheBilinearFieldSeesSubCellShifts) {
  PreparedScan one;
  one.x = {scan.x.front()};
  one.y = {scan.y.front()};
  std::set<double> by_cell, bilinear;
  for (int k = 0; k < 50; ++k) {
    const Pose2 at{truth.x + 0.001 * k, truth.y + 0.001 * k, truth.theta};
    by_cell.insert(model.log_likelihood(grid, at, one));
    bilinear.insert(model.log_likelihood(grid, at, one, FieldLookup::kBilinear));
  }
  EXPECT_LE(by_cell.size(), 3u);  // two cell borders crossed at most
  EXPECT_GE(bilinear.size(), 45u);
  // Both peak at the true pose.
  const double at_truth = model.log_likelihood(grid, truth, scan, FieldLookup::kBilinear);
  EXPECT_GT(at_truth, model.log_likelihood(grid, {truth.x, truth.y + 0.1, truth.theta}, scan, FieldLookup::kBilinear));
  EXPECT_GT(at_truth, model.log_likelihood(grid, {truth.x, truth.y, truth.theta + 0.05}, scan, FieldLookup::kBilinear));
}

// The bilinear field's peak sits where the cell centres put the walls (up to half a cell
// from the true wall, as the cell lookup's): the same tolerance as the cell match.
TEST_F(ScanMatcherTest, TheBilinearMatchRecoversAnOdometryError) {
  const ScanMatcher matcher(ScanMatcherOptions{}, model);
  const Pose2 start{truth.x + 0.15, truth.y - 0.1, truth.theta + 0.06};
  const MatchResult r = matcher.match(grid, start, scan, 0.0, FieldLookup::kBilinear);
  EXPECT_TRUE(r.ok);
  EXPECT_NEAR(r.pose.x, truth.x, 0.03);
  EXPECT_NEAR(r.pose.y, truth.y, 0.03);
  EXPECT_NEAR(r.pose.theta, truth.theta, 0.01);
}

TEST_F(ScanMatcherTest, RecoversAnOdometryError) {
  const ScanMatcher matcher(ScanMatcherOptions{}, model);
  const MatchResult r = matcher.match(grid, {truth.x + 0.15, truth.y - 0.1, truth.theta + 0.06}, scan);
  EXPECT_TRUE(r.ok);
  EXPECT_NEAR(r.pose.x, truth.x, 0.03);
  EXPECT_NEAR(r.pose.y, truth.y, 0.03);
  EXPECT_NEAR(r.pose.theta, truth.theta, 0.01);
  EXPECT_GT(r.hit_ratio, 0.8);
}

// A turn the odometry misread by 0.15 rad: a climb whose first angular step covers the
// odometry's rotation std reaches it, and the extra levels keep the finest step.
TEST_F(ScanMatcherTest, AngularReachRecoversAMisreadTurn) {
  const ScanMatcher matcher(ScanMatcherOptions{}, model);
  const Pose2 start{truth.x + 0.05, truth.y, truth.theta - 0.15};
  const MatchResult r = matcher.match(grid, start, scan, 0.1);
  EXPECT_TRUE(r.ok);
  EXPECT_NEAR(r.pose.x, truth.x, 0.04);
  EXPECT_NEAR(r.pose.y, truth.y, 0.04);
  EXPECT_NEAR(r.pose.theta, truth.theta, 0.01);
  const MatchResult fine = matcher.match(grid, start, scan);
  EXPECT_LT(fine.log_likelihood, r.log_likelihood);  // the 0.05 rad climb stops short
}

TEST_F(ScanMatcherTest, FailsWhenTheScanDoesNotFitTheMap) {
  const ScanMatcher matcher(ScanMatcherOptions{}, model);
  const PreparedScan wrong =
      prepare_scan(test::simulate_scan({{0, 0, 1, 0}, {1, 0, 1, 1}}, {0.5, 0.5, 0}, {}), LikelihoodOptions{});
  EXPECT_FALSE(matcher.match(grid, truth, wrong).ok);
}

// The kernel's mean (Grisetti 2007 eq. (12)) around a mode a little off the truth lies on the
// truth, far tighter than the odometry model's ~5 cm for a 0.5 m step.
TEST_F(ScanMatcherTest, ProposalMeanLiesOnTheTruth) {
  const OdometryMotionModel motion;
  const Pose2 u{0.5, 0.0, 0.1};
  const Pose2 previous = truth.compose(u.inverse());
  for (const Pose2 off : {Pose2{0.02, 0.0, 0.0}, Pose2{0.0, -0.02, 0.0}, Pose2{0.0, 0.0, 0.01}}) {
    const Pose2 mode = truth.compose(off);
    const ProposalMean d = improved_proposal(grid, previous, u, mode, scan, model, motion, {}, FieldLookup::kBilinear);
    ASSERT_TRUE(std::isfinite(d.log_eta));
    EXPECT_LT(std::hypot(d.mean.x - truth.x, d.mean.y - truth.y), 0.02);
    EXPECT_LT(std::abs(normalize_angle(d.mean.theta - truth.theta)), 0.01);
  }
}

// As GMapping's released code: the particle is the kernel's mean (Grisetti 2007 eq. (12)),
// its spread comes from the motion-model draw of the matcher's start.
// A start drawn far off (7 deg of rotation std here) may climb to another optimum of this
// small map; eta (eq. (14)) weighs it down.
TEST_F(ScanMatcherTest, TheParticleIsTheMeanAroundAMatchFromADrawnStart) {
  const RbpfOptions options;
  const OdometryMotionModel motion(options.motion);
  const ScanMatcher matcher(options.matcher, model);
  const ParticleStepModels models{options, motion, model, matcher};
  const Pose2 u{0.5, 0.0, 0.1};
  const Pose2 previous = truth.compose(u.inverse());
  std::set<double> xs;
  int near = 0;
  double best_weight = -INFINITY;
  bool best_is_near = false;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    Pose2 pose = previous, estimate;
    double log_weight = 0.0;
    ASSERT_FALSE(draw_particle(models, grid, pose, log_weight, u, scan, true, rng, &estimate));
    EXPECT_DOUBLE_EQ(pose.x, estimate.x);
    EXPECT_DOUBLE_EQ(pose.y, estimate.y);
    EXPECT_DOUBLE_EQ(pose.theta, estimate.theta);
    const bool is_near = std::hypot(pose.x - truth.x, pose.y - truth.y) < 0.03 &&
                         std::abs(normalize_angle(pose.theta - truth.theta)) < 0.01;
    near += is_near ? 1 : 0;
    if (log_weight > best_weight) {
      best_weight = log_weight;
      best_is_near = is_near;
    }
    xs.insert(pose.x);
  }
  EXPECT_GE(near, 10);
  EXPECT_TRUE(best_is_near);
  EXPECT_GT(xs.size(), 1u);  // different starts, different particles
}

}  // namespace
}  // namespace lookahead::slam
