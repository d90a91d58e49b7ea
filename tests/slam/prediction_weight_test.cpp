// SPDX-License-Identifier: MIT
// P-SLAM in the filter (Chang et al. 2007, eq. 21-23): hypotheses enter the weights only
// through the predicted beams, a wrong hypothesis is caught by the hit-ratio rule, and with
// prediction off the filter is the plain RBPF bit for bit.
#include <gtest/gtest.h>

#include <memory>

#include "lookahead/slam/rbpf/hypothesis_weight.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"
#include "test_world.hpp"

namespace lookahead::slam {
namespace {

// An L-shaped corridor: along x (y in [0, 2]) up to x = 12, then a branch up along y
// (x in [10, 12]) that the robot cannot see from the start.
std::vector<test::Segment> l_corridor() {
  return {{0, 0, 12, 0}, {12, 0, 12, 20}, {0, 2, 10, 2}, {10, 2, 10, 20}, {0, 0, 0, 2}, {10, 20, 12, 20}};
}

// The branch as a hypothesis would predict it: walls at x = left and x = right, free between.
std::shared_ptr<HypothesisMap> branch_hypothesis(double left, double right) {
  auto h = std::make_shared<HypothesisMap>();
  for (double y = 2.3; y < 19.9; y += 0.05) {
    for (double x = left; x <= right + 1e-9; x += 0.05) {
      const bool wall = x < left + 0.05 || x > right - 0.05;
      h->grid.add_log_odds(h->grid.cell_at(x, y), wall ? 3000 : -1000);
    }
  }
  h->similarity = 0.7;
  return h;
}

// Drives along the corridor and turns up into the branch (exact odometry).
std::vector<LaserScan> drive_into_branch() {
  std::vector<LaserScan> scans;
  Pose2 pose{1.0, 1.0, 0.0};
  double t = 0;
  for (int i = 0; i < 100; ++i) {
    scans.push_back(test::simulate_scan(l_corridor(), pose, pose, t += 0.1));
    pose = pose.compose({0.1, 0, 0});
  }
  for (int i = 0; i < 16; ++i) {
    scans.push_back(test::simulate_scan(l_corridor(), pose, pose, t += 0.1));
    pose = pose.compose({0, 0, M_PI / 32});
  }
  for (int i = 0; i < 60; ++i) {
    scans.push_back(test::simulate_scan(l_corridor(), pose, pose, t += 0.1));
    pose = pose.compose({0.1, 0, 0});
  }
  return scans;
}

RbpfOptions options(bool predict) {
  RbpfOptions o;
  o.particles = 10;
  o.seed = 5;
  o.threads = 1;
  o.linear_update = 0.3;
  o.prediction.enabled = predict;
  return o;
}

Rbpf run(const RbpfOptions& o, const std::shared_ptr<HypothesisMap>& h) {
  Rbpf filter(o);
  const std::vector<LaserScan> scans = drive_into_branch();
  filter.add_scan(scans.front());
  if (h) filter.add_hypothesis(h);
  for (std::size_t i = 1; i < scans.size(); ++i) filter.add_scan(scans[i]);
  return filter;
}

TEST(PredictionWeight, EndPointsSplitIntoExploredAndPredicted) {
  OccupancyGrid map;
  map.add_log_odds(map.cell_at(1.0, 1.0), -1000);  // explored: the cell at (1, 1) only
  const auto h = branch_hypothesis(10, 12);
  const LikelihoodFieldModel model({}, map);
  PreparedScan scan;  // three end points, robot at the origin
  scan.x = {1.0f, 11.0f, 11.95f};
  scan.y = {1.0f, 5.0f, 5.0f};
  const HypothesisScore s = score_on_hypotheses(map, {}, scan, {h}, {Pose2{}}, model);
  EXPECT_EQ(s.predicted_beams, 2);  // (1, 1) is z_e; the other two land on the hypothesis
  EXPECT_EQ(s.hits, 1);             // (11.95, 5) is on the predicted wall, (11, 5) is not
  EXPECT_DOUBLE_EQ(s.hit_ratio(), 0.5);
  // Offsets move the particle's frame into the hypothesis frame.
  const HypothesisScore moved = score_on_hypotheses(map, {}, scan, {h}, {Pose2{0.95, 0, 0}}, model);
  EXPECT_EQ(moved.hits, 1);  // (11.95, 5) now lands on (12.9, 5): off the map; (11, 5) -> wall
}

TEST(PredictionWeight, OffOrWithoutHypothesesTheFilterIsPlainRbpf) {
  const Rbpf plain = run(options(false), nullptr);
  const Rbpf ignored = run(options(false), branch_hypothesis(10, 12));  // off: hypothesis ignored
  const Rbpf empty = run(options(true), nullptr);
  for (const Rbpf* f : {&ignored, &empty}) {
    ASSERT_EQ(f->particles().size(), plain.particles().size());
    for (std::size_t i = 0; i < plain.particles().size(); ++i) {
      EXPECT_EQ(f->particles()[i].pose.x, plain.particles()[i].pose.x);
      EXPECT_EQ(f->particles()[i].pose.theta, plain.particles()[i].pose.theta);
      EXPECT_EQ(f->particles()[i].log_weight, plain.particles()[i].log_weight);
    }
  }
  EXPECT_EQ(ignored.statistics().hypotheses_added, 0u);
}

TEST(PredictionWeight, ACorrectHypothesisEntersTheWeights) {
  const Rbpf f = run(options(true), branch_hypothesis(10, 12));
  EXPECT_EQ(f.statistics().hypotheses_added, 1u);
  EXPECT_GT(f.statistics().prediction_used, 3u);
  EXPECT_LT(f.statistics().prediction_rejected, f.statistics().prediction_used);
  RecordProperty("used", static_cast<int>(f.statistics().prediction_used));
  RecordProperty("rejected", static_cast<int>(f.statistics().prediction_rejected));
}

TEST(PredictionWeight, AWrongHypothesisIsRejectedByTheHitRatio) {
  const Rbpf f = run(options(true), branch_hypothesis(8.5, 13.5));  // walls 1.5 m off
  EXPECT_GT(f.statistics().prediction_rejected, 3u);
  EXPECT_LT(f.statistics().prediction_used, f.statistics().prediction_rejected);
  RecordProperty("used", static_cast<int>(f.statistics().prediction_used));
  RecordProperty("rejected", static_cast<int>(f.statistics().prediction_rejected));
}

TEST(PredictionWeight, ImpossibleOptionsAreRejected) {
  RbpfOptions o = options(true);
  o.prediction.hit_ratio_threshold = 1.5;
  EXPECT_THROW(Rbpf{o}, std::invalid_argument);
  o = options(true);
  o.prediction.max_hypotheses = 0;
  EXPECT_THROW(Rbpf{o}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam
