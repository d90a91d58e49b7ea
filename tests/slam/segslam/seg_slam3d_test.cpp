// SPDX-License-Identifier: MIT
// SegSLAM on octree submaps over a short simulated garage drive.
#include "lookahead/slam/segslam/seg_slam3d.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "garage_drive.hpp"
#include "lookahead/slam/segslam/octree_map_samples.hpp"
#include "lookahead/slam/segslam/segslam_config.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam::segslam {
namespace {

// The first 21 m of the garage loop with a strong yaw bias, segments of at least 5 sweeps:
// the filter segments, reconstructs one pose per sweep, stays near the truth, and a full map
// sample pastes every segment of the chain.
TEST(SegSlam3d, ShortGarageSegmentSegmentsAndStaysNearTheTruth) {
  World3 w = make_garage_world(1, 0.2);
  w.route.resize(3);
  CaveCrawlerOptions robot;
  robot.dead_reckoning.yaw_bias = 0.01;
  const RangeLog3 log = simulate_cave_crawler(w, robot, 3);
  SegSlam3dOptions o;
  o.filter.particles = 5;
  o.filter.threads = 2;
  o.segslam.segmentation.min_segment_updates = 5;
  o.segslam.segmentation.max_motion_error = 0.2;
  o.segslam.offline.particle_chain = true;  // off in 3D's defaults; tested here
  SegSlam3d filter(o);
  for (const RangeSweep& s : log.sweeps) filter.add_sweep(s);
  filter.finish();
  const auto& st = filter.statistics();
  EXPECT_GE(st.segmentations, 1U);
  EXPECT_EQ(st.updates, log.sweeps.size());
  EXPECT_GE(filter.segmap().live_count(), 1U);
  EXPECT_EQ(filter.trajectory_at_every_sweep(0).size(), log.sweeps.size());
  const Eigen::Vector3d truth = log.sweeps.back().truth->translation();
  const double dead_reckoning = (log.sweeps.back().odometry.translation() - truth).norm();
  const double error = (filter.estimate().position() - truth).norm();
  std::printf("%zu sweeps, %zu segmentations; dead reckoning %.2f m, SegSLAM %.2f m\n", log.sweeps.size(),
              st.segmentations, dead_reckoning, error);
  // Five-sweep segments leave each submap little to correct against (1.26 m against 1.89 m
  // dead reckoning when written): the bound is that SLAM beats dead reckoning.
  EXPECT_LT(error, dead_reckoning);
  const SegmentedPath path = filter.segmented_trajectory(filter.best_particle());
  EXPECT_GE(path.pieces.size(), 2U);
  std::mt19937_64 rng(1);
  const OctreeMapSample sample = sample_full_map(filter, filter.best_particle(), rng);
  EXPECT_EQ(sample.placed.size(), path.pieces.size());  // no loop: the sample is the chain
  // The picture draws the sample's own paths: one piece per placed submap, every path pose.
  const SegmentedPath drawn = sample_paths(filter, sample);
  ASSERT_EQ(drawn.pieces.size(), sample.placed.size());
  std::size_t poses = 0, drawn_poses = 0;
  for (std::size_t i = 0; i < sample.placed.size(); ++i) {
    poses +=
        (i == 0 ? filter.particles().at(sample.particle).submap : filter.segmap().at(sample.placed[i].id)).path.size();
    drawn_poses += drawn.pieces[i].size();
  }
  EXPECT_EQ(drawn_poses, poses);
  EXPECT_GT(sample.map.known_voxels(), 1000U);
  EXPECT_GT(sample.entropy, 0.0);
  // The best particle's chain as a map (offline.particle_chain): its path is the particle's
  // eq. 11 trajectory, and the search returns it only where its entropy is least.
  const OctreeMapSample chain = particle_chain_sample(filter, filter.best_particle());
  EXPECT_TRUE(chain.chain);
  EXPECT_EQ(chain.placed.size(), path.pieces.size());
  const std::vector<Pose4> along = sample_trajectory_at_every_sweep(filter, chain);
  const std::vector<Pose4> trajectory = filter.trajectory_at_every_sweep(filter.best_particle());
  ASSERT_EQ(along.size(), trajectory.size());
  for (std::size_t i = 0; i < along.size(); ++i) {
    ASSERT_NEAR((along[i].position() - trajectory[i].position()).norm(), 0.0, 1e-9) << "sweep " << i;
  }
  const OctreeMinEntropyResult best = min_entropy_search(filter, 2, 1);
  EXPECT_NEAR(best.chain_entropy, chain.entropy, 1e-6 * chain.entropy);
  EXPECT_LE(best.best.entropy, best.chain_entropy);
  for (double h : best.entropies) EXPECT_LE(best.best.entropy, h);
}

// Driving the garage's first aisle back and forth (the later legs re-enter the first legs'
// submaps), the particles' capped searches on one submap are searched together: fewer
// searches than regions asked for, the re-entries found, the robot kept within 1 m.
TEST(SegSlam3d, CappedSearchesOnOneSubmapAreSearchedTogether) {
  SegSlam3d filter(test_data::aisle_options(8));
  test_data::run_filter(filter, test_data::aisle_back_and_forth());
  const SegSlam3dStatistics& st = filter.statistics();
  const std::size_t capped_regions = st.match_attempts - st.wide_attempts;
  std::printf("%zu capped searches for %zu regions (%zu requests), %zu matches\n", st.capped_searches, capped_regions,
              st.match_requests, st.matches);
  EXPECT_GT(st.capped_searches, 0U);
  EXPECT_LT(st.capped_searches, capped_regions);
  EXPECT_GT(st.matches, 0U);
  const Eigen::Vector3d truth = test_data::aisle_back_and_forth().sweeps.back().truth->translation();
  EXPECT_LT((filter.estimate().position() - truth).norm(), 1.0);
}

// The wide re-entry stage searches on this short drive when its reach is on, and never with
// max_radius 0. (The capped search is kept at its fixed 2 m so that the stage triggers.)
TEST(SegSlam3d, WideStageRunsOnlyWhenItsReachIsOn) {
  const auto wide_searches = [](double max_radius) {
    SegSlam3dOptions o = test_data::aisle_options(3);
    o.segslam.matching.max_search_radius = 0;
    o.extras.wide.max_radius = max_radius;
    SegSlam3d filter(o);
    test_data::run_filter(filter, test_data::aisle_back_and_forth());
    return filter.statistics().wide_attempts;
  };
  EXPECT_GT(wide_searches(8.0), 0U);
  EXPECT_EQ(wide_searches(0.0), 0U);
}

TEST(SegSlam3d, RejectsImpossibleOptions) {
  SegSlam3dOptions o;
  o.extras.window_points = 3;
  EXPECT_THROW(SegSlam3d{o}, std::invalid_argument);
  o = {};
  o.segslam.matching.bin_size = -1;
  EXPECT_THROW(SegSlam3d{o}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam::segslam
