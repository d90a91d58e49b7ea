// SPDX-License-Identifier: MIT
// On a real KTH plan with long detours, goals the stuck clock gives up while the robot drives
// to them are blacklisted for good. Before calling a mission trapped, such goals get a second
// chance with progress measured along the path.
#include <gtest/gtest.h>

#include <filesystem>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/world_source.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;

// Plan 50010540, seed 3, utility: the setup of config/study/kth_p2_more.yaml (P2 Explore's
// 360 deg, 12 m laser; a 0.1 m robot; the map built at the true pose).
MissionOptions kth_p2_more(std::uint64_t seed) {
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.strategy = "utility";
  o.seed = seed;
  o.time_limit = 3600;
  o.coverage_goal = 0.95;
  o.frame_period = 0;
  o.robot.radius = 0.1;
  o.laser.fov = 6.283185307;
  o.laser.max_range = 12;
  o.laser.angular_resolution = 0.008726646;
  o.frontiers.cluster_gap = 2;
  // A one-hit costmap threshold and a stuck clock without detour progress: a setup whose
  // doors the margin flickers on, which gives goals up for good (the default keeps
  // progress on detours and reaches 95 % with fewer give-ups).
  o.planner.costmap.occupied_threshold = 0.65;
  o.detour_progress = false;
  o.harmonize();
  return o;
}

// Goals given up for good come back (the second chance) or are never given up (paths the
// margin closes are kept): either way the mission reaches its goal, never `trapped`.
TEST(MissionSecondChance, FlickeringDoorsDoNotTrapTheMission) {
  const fs::path plan =
      fs::path(LOOKAHEAD_SHARED_DIR) / "data/floorplans/kth/p2explore/floor_plans/50010540.png0.png0.png";
  if (!fs::exists(plan)) GTEST_SKIP() << plan << " missing";
  WorldSpec spec;
  spec.name = plan.string();
  spec.image_resolution = 0.2;
  spec.pixel_rule = "only_white";
  const MissionOptions o = kth_p2_more(3);
  const GeneratedWorld w = load_world(spec, o.robot.radius);
  Mission m(w.world, w.start, o);
  const MissionStatus s = m.run();
  EXPECT_EQ(s, MissionStatus::kCoverageReached) << to_string(s) << " at " << m.coverage();
  EXPECT_GE(m.statistics().forgiven_goals + m.statistics().kept_paths, 1);
  EXPECT_EQ(m.statistics().collisions, 0);
}

}  // namespace
}  // namespace lookahead::exploration
