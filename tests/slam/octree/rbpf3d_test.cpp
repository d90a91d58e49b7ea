// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf3d/rbpf3d.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/rbpf3d/slam3d_config.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam {
namespace {

// A short garage segment (the first 21 m with a turn) with a strong yaw bias: the filter's
// estimate stays within 1 m of the truth and at most half the dead-reckoning error (seed 3:
// 0.66 m against 1.89 m when written).
TEST(Rbpf3d, ShortGarageSegmentStaysWithinABound) {
  World3 w = make_garage_world(1, 0.2);
  w.route.resize(3);
  CaveCrawlerOptions robot;
  robot.dead_reckoning.yaw_bias = 0.01;
  robot.laser.lines_per_sweep = 15;
  robot.laser.sweep_period = 0.5;  // a sweep every 0.5 m, as coarse as at 1 m/s, 30 lines
  const RangeLog3 log = simulate_cave_crawler(w, robot, 3);
  Rbpf3dOptions o;
  o.particles = 10;
  o.threads = 2;
  Rbpf3d filter(o);
  for (const RangeSweep& s : log.sweeps) filter.add_sweep(s);
  const Eigen::Vector3d truth = log.sweeps.back().truth->translation();
  const double dead_reckoning_error = (log.sweeps.back().odometry.translation() - truth).norm();
  const double error = (filter.mean_position() - truth).norm();
  std::printf("dead reckoning %.2f m, filter %.2f m\n", dead_reckoning_error, error);
  EXPECT_GT(dead_reckoning_error, 1.0);
  EXPECT_LT(error, 1.0);
  EXPECT_LT(error, 0.5 * dead_reckoning_error);
  EXPECT_EQ(filter.trajectory(0).size(), log.sweeps.size());
}

TEST(Rbpf3d, ResampledParticlesShareTheirMaps) {
  World3 w = make_garage_world(1, 0.2);
  w.route.resize(3);
  const RangeLog3 log = simulate_cave_crawler(w, {}, 1);
  Rbpf3dOptions o;
  o.particles = 6;
  o.resample_threshold = 1.0;  // resample after every update
  Rbpf3d filter(o);
  for (const RangeSweep& s : log.sweeps) filter.add_sweep(s);
  std::vector<const EvidenceOctree*> maps;
  std::size_t full = 0;
  for (const Particle3& p : filter.particles()) {
    maps.push_back(&p.map);
    full += p.map.memory().total_bytes;
  }
  EXPECT_GT(filter.statistics().resamplings, 0U);
  std::printf("6 maps: %zu bytes alone, %zu stored\n", full, EvidenceOctree::distinct_bytes(maps));
  // Each map was written by its last sweep after the last resampling; on this 21 m map a
  // sweep touches a good part of it, so the bound is loose (the full loop shares 11x).
  EXPECT_LT(static_cast<double>(EvidenceOctree::distinct_bytes(maps)), 0.75 * static_cast<double>(full));
}

// config/slam3d/default.yaml documents the defaults: it must say exactly what the code does.
TEST(Slam3dConfig, DefaultYamlMatchesTheCode) {
  std::ifstream in(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/slam3d/default.yaml");
  ASSERT_TRUE(in) << "config/slam3d/default.yaml missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), dump_slam3d_options({}))
      << "regenerate with: lookahead config dump slam3d > config/slam3d/default.yaml";
  const Slam3dOptions back = parse_slam3d_options(text.str(), "default.yaml");
  EXPECT_EQ(dump_slam3d_options(back), text.str());
}

TEST(Slam3dConfig, UnknownKeysAndImpossibleValuesAreErrors) {
  EXPECT_THROW(parse_slam3d_options("filter:\n  particlez: 3\n", "x.yaml"), ParseError);
  EXPECT_THROW(parse_slam3d_options("map:\n  resolution: -1\n", "x.yaml"), ParseError);
  EXPECT_THROW(parse_slam3d_options("robot:\n  speed: fast\n", "x.yaml"), ParseError);
  EXPECT_EQ(parse_slam3d_options("filter:\n  particles: 7\n", "x.yaml").filter.particles, 7);
}

}  // namespace
}  // namespace lookahead::slam
