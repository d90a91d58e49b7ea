// SPDX-License-Identifier: MIT
// Narrow doors on real KTH plans (0.4 m, two pixels of a 0.2 m/pixel plan), whose jambs the
// safety margin closes and opens again from one scan to the next: the mission still reaches
// its goal, never `trapped` and never held at a door until the time limit.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/world_source.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;

// The setup of config/study/kth_all.yaml: P2 Explore's 360 deg, 12 m laser, a 0.1 m robot,
// the map built at the true pose.
MissionOptions kth_p2(const std::string& strategy, std::uint64_t seed) {
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.strategy = strategy;
  o.seed = seed;
  o.time_limit = 1800;
  o.coverage_goal = 0.95;
  o.frame_period = 0;
  o.robot.radius = 0.1;
  o.laser.fov = 6.283185307;
  o.laser.max_range = 12;
  o.laser.angular_resolution = 0.008726646;
  o.frontiers.cluster_gap = 2;
  o.harmonize();
  return o;
}

std::optional<GeneratedWorld> kth_plan(const std::string& file, double robot_radius) {
  const fs::path plan = fs::path(LOOKAHEAD_SHARED_DIR) / "data/floorplans/kth/p2explore/floor_plans" / file;
  if (!fs::exists(plan)) return std::nullopt;
  WorldSpec spec;
  spec.name = plan.string();
  spec.image_resolution = 0.2;
  spec.pixel_rule = "only_white";
  return load_world(spec, robot_radius);
}

// Plan 50010540, seed 3, utility, with a one-hit costmap threshold and a stuck clock without
// detour progress: goals the stuck clock gives up while the robot drives to them are
// blacklisted for good. They come back (the second chance before `trapped`) or are never
// given up (paths the margin closes are kept).
TEST(MissionKthDoors, FlickeringDoorsDoNotTrapTheMission) {
  MissionOptions o = kth_p2("utility", 3);
  o.time_limit = 3600;
  o.planner.costmap.occupied_threshold = 0.65;
  o.detour_progress = false;
  o.harmonize();
  const auto w = kth_plan("50010540.png0.png0.png", o.robot.radius);
  if (!w) GTEST_SKIP() << "plan 50010540 missing";
  Mission m(w->world, w->start, o);
  const MissionStatus s = m.run();
  EXPECT_EQ(s, MissionStatus::kCoverageReached) << to_string(s) << " at " << m.coverage();
  EXPECT_GE(m.statistics().forgiven_goals + m.statistics().kept_paths, 1);
  EXPECT_EQ(m.statistics().collisions, 0);
}

// Plan 0510034869, seed 1, distance advantage: the robot stands in a passage with a 0.4 m door
// at each end, and every goal lies beyond both. The margin closes whichever door the robot
// walks up to; a replan through the other door, taken each time, sent it to and fro between
// them from 300 s to the time limit (54 % explored). One way round per goal keeps the path
// it swapped to.
TEST(MissionKthDoors, TwoDoorsDoNotHoldTheRobotToAndFro) {
  const MissionOptions o = kth_p2("advantage", 1);
  const auto w = kth_plan("0510034869_A-40.png0.png0.png", o.robot.radius);
  if (!w) GTEST_SKIP() << "plan 0510034869 missing";
  Mission m(w->world, w->start, o);
  const MissionStatus s = m.run();
  EXPECT_EQ(s, MissionStatus::kCoverageReached) << to_string(s) << " at " << m.coverage();
  EXPECT_LT(m.time(), 900.0);
  EXPECT_GE(m.statistics().kept_paths, 1);
  EXPECT_EQ(m.statistics().collisions, 0);
}

}  // namespace
}  // namespace lookahead::exploration
