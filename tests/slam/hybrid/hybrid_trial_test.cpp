// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <algorithm>

#include "lookahead/slam/hybrid/study.hpp"
#include "lookahead/slam/hybrid/trial.hpp"

namespace lookahead::slam::hybrid {
namespace {

// A smaller world than the paper's (60 m, a loop of about 160 m) so the test takes seconds.
SimulationOptions small_world() {
  SimulationOptions s;
  s.world_size = 60.0;
  s.features = 25;
  s.inset = 8.0;
  s.inset_jitter = 3.0;
  s.loop_overlap = 15.0;
  return s;
}

HybridOptions clean(int particles) {
  HybridOptions o;
  o.fastslam.particles = particles;
  return o;
}

TEST(HybridTrial, ShortCleanTrialClosesItsLoop) {
  const HybridOptions o = clean(100);
  const SimulatedRun run = simulate(small_world(), o.sensor, 1.0, 0.0, 2, 2);
  ASSERT_GT(run.path_length, 150.0);
  const TrialResult r = run_trial(FilterKind::kHybrid, run, o, 2, {}, false);
  EXPECT_TRUE(r.success) << "failed at step " << r.failed_at;
  EXPECT_GT(r.fusions, 10);
  // Closing the loop: back at the start the uncertainty drops well below its peak, and the
  // estimate is within a few decimetres of the truth.
  const double peak = *std::max_element(r.trace.begin(), r.trace.end());
  EXPECT_LT(r.trace.back(), 0.5 * peak);
  const Pose2 end = run.steps.back().truth, est = r.estimate.back();
  EXPECT_LT(std::hypot(end.x - est.x, end.y - est.y), 0.5);
  // Every true feature near the path is in the map once (no duplicates after the loop).
  int mapped = 0;
  for (const auto& f : run.features) {
    int near = 0;
    for (const auto& m : r.map) near += (m.mean - f).norm() < 1.0;
    EXPECT_LE(near, 1);
    mapped += near;
  }
  EXPECT_GE(mapped, 20);
}

// The paper's FASTSLAM baseline loses its uncertainty: far more confident than HYBRID.
TEST(HybridTrial, FastSlamAloneBecomesOverconfident) {
  const HybridOptions o = clean(100);
  const SimulatedRun run = simulate(small_world(), o.sensor, 1.0, 0.0, 2, 2);
  const TrialResult fast = run_trial(FilterKind::kFastSlam, run, o, 2, {}, true);
  const TrialResult hybrid = run_trial(FilterKind::kHybrid, run, o, 2, {}, true);
  EXPECT_FALSE(fast.success);
  EXPECT_TRUE(hybrid.success);
}

TEST(HybridStudy, SameResultForAnyThreadCount) {
  StudyOptions s;
  s.alphas = {1.0, 0.4};
  s.betas = {0.0, 0.04};
  s.trials = 1;
  s.worlds = 1;
  SimulationOptions sim = small_world();
  sim.world_size = 40.0;
  sim.features = 15;
  sim.loop_overlap = 5.0;
  const HybridOptions o = clean(20);
  const std::vector<FilterKind> filters = {FilterKind::kEkf, FilterKind::kHybrid};
  s.threads = 1;
  const StudyResult one = run_study(s, o, sim, filters);
  s.threads = 2;
  const StudyResult two = run_study(s, o, sim, filters);
  ASSERT_EQ(one.cells.size(), 4u);
  for (std::size_t i = 0; i < one.cells.size(); ++i) {
    EXPECT_EQ(one.cells[i].successes, two.cells[i].successes);
    EXPECT_DOUBLE_EQ(one.cells[i].simulated_s, two.cells[i].simulated_s);
  }
}

TEST(Simulation, SensorMatchesTheClutterModel) {
  SensorOptions sensor;
  const SimulatedRun clean_run = simulate(small_world(), sensor, 1.0, 0.0, 1, 1);
  const SimulatedRun cluttered = simulate(small_world(), sensor, 0.4, 0.06, 1, 1);
  std::size_t clean_z = 0, detections = 0, all = 0;
  for (const auto& s : clean_run.steps) {
    clean_z += s.observations.size();
    EXPECT_EQ(static_cast<int>(s.observations.size()), s.true_detections);  // no clutter
  }
  for (const auto& s : cluttered.steps)
    detections += static_cast<std::size_t>(s.true_detections), all += s.observations.size();
  // alpha = 0.4 of the visible features, plus beta = 0.06 false alarms per visible feature.
  const double visible = static_cast<double>(clean_z) / static_cast<double>(clean_run.steps.size());
  const double steps = static_cast<double>(cluttered.steps.size());
  EXPECT_NEAR(static_cast<double>(detections) / steps, 0.4 * visible, 0.1 * visible);
  EXPECT_NEAR(static_cast<double>(all - detections) / steps, 0.06 * visible, 0.03 * visible);
}

}  // namespace
}  // namespace lookahead::slam::hybrid
