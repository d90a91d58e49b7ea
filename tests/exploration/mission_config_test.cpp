// SPDX-License-Identifier: MIT
// The mission YAML loader: round trip, errors that name file:line, key and value, the slam
// section's line numbers, and the shipped defaults.
#include "lookahead/exploration/mission_config.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {
namespace {

// Expects a ParseError from `yaml` and returns it for the caller's checks.
slam::ParseError parse_error(const std::string& yaml) {
  try {
    parse_mission_options(yaml, "my.yaml");
  } catch (const slam::ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return slam::ParseError("", 0, "", "", "");
}

TEST(MissionConfig, DumpReadsBackToTheSameOptions) {
  MissionOptions o = MissionOptions::defaults();
  o.strategy = "utility";
  o.pose_source = PoseSource::kTruth;
  o.seed = 42;
  o.robot.radius = 0.2;
  o.laser.max_range = 6.5;
  o.planner.algorithm = planner::PlannerAlgorithm::kInformedRrtStar;
  o.planner.simplify = false;
  o.planner.max_samples = 1234;
  o.slam.particles = 12;
  o.harmonize();
  const MissionOptions back = parse_mission_options(dump_mission_options(o), "dump");
  EXPECT_EQ(dump_mission_options(back), dump_mission_options(o));
  EXPECT_EQ(back.strategy, "utility");
  EXPECT_EQ(back.pose_source, PoseSource::kTruth);
  EXPECT_EQ(back.planner.algorithm, planner::PlannerAlgorithm::kInformedRrtStar);
  EXPECT_EQ(back.slam.particles, 12);
  EXPECT_EQ(back.slam.seed, 44u);  // derived from mission.seed by harmonize()
  EXPECT_DOUBLE_EQ(back.slam.likelihood.max_range, 6.5);
  EXPECT_DOUBLE_EQ(back.planner.costmap.robot_radius, 0.2 + back.safety_margin);
}

TEST(MissionConfig, LeftOutKeysKeepTheBase) {
  const MissionOptions o = parse_mission_options("robot:\n  max_speed: 0.4\n", "x");
  EXPECT_DOUBLE_EQ(o.robot.max_speed, 0.4);
  EXPECT_DOUBLE_EQ(o.follower.max_linear_speed, 0.4);  // harmonized
  EXPECT_EQ(o.slam.particles, MissionOptions::defaults().slam.particles);
  EXPECT_EQ(dump_mission_options(parse_mission_options("", "x")), dump_mission_options(MissionOptions::defaults()));
}

TEST(MissionConfig, UnknownKeyNamesFileLineAndKey) {
  const slam::ParseError e = parse_error("mission:\n  seed: 3\nrobot:\n  radius: 0.2\n  raduis: 0.3\n");
  EXPECT_EQ(e.file(), "my.yaml");
  EXPECT_EQ(e.line(), 5u);
  EXPECT_EQ(e.field(), "robot.raduis");
  EXPECT_EQ(parse_error("\nrobots:\n  radius: 0.2\n").line(), 2u);
}

TEST(MissionConfig, BadEnumValueNamesTheValue) {
  slam::ParseError e = parse_error("mission:\n  pose_source: gps\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "mission.pose_source");
  EXPECT_EQ(e.value(), "gps");
  e = parse_error("planner:\n  time_budget: 0.5\n  algorithm: rrt\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "planner.algorithm");
  EXPECT_EQ(e.value(), "rrt");
  e = parse_error("slam:\n  proposal:\n    kind: standard\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "proposal.kind");
  EXPECT_EQ(e.value(), "standard");
  e = parse_error("mission:\n  detour_progress: sometimes\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "mission.detour_progress");
  EXPECT_EQ(e.value(), "sometimes");
  e = parse_error("laser:\n  max_range: far\n");
  EXPECT_EQ(e.field(), "laser.max_range");
  EXPECT_EQ(e.value(), "far");
}

TEST(MissionConfig, ImpossibleValuesAreParseErrorsNamingTheFile) {
  EXPECT_EQ(parse_error("mission:\n  strategy: random_walk\n").file(), "my.yaml");
  EXPECT_EQ(parse_error("mission:\n  coverage_goal: 1.5\n").file(), "my.yaml");
  EXPECT_EQ(parse_error("robot:\n  radius: -1\n").file(), "my.yaml");
  EXPECT_EQ(parse_error("[1, 2]\n").line(), 1u);
  EXPECT_EQ(parse_error("robot: 3\n").field(), "robot");
}

// The slam body goes to the SLAM loader; its errors keep this file's line numbers.
TEST(MissionConfig, GarbageRateOffsetNamesLineAndValue) {
  slam::ParseError e = parse_error("mission:\n  strategy: rate\n  rate_offset: four\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "mission.rate_offset");
  EXPECT_EQ(e.value(), "four");
  e = parse_error("mission:\n  rate_offset: -2\n");  // a path can not cost less than nothing
  EXPECT_EQ(e.file(), "my.yaml");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.value(), "-2");
  EXPECT_EQ(parse_error("mission:\n  rate_offset: 0\n").field(), "mission.rate_offset");
  EXPECT_DOUBLE_EQ(parse_mission_options("mission:\n  rate_offset: 2.5\n", "x").rate_offset, 2.5);
}

TEST(MissionConfig, SlamSectionKeepsLineNumbers) {
  const MissionOptions o =
      parse_mission_options("mission:\n  seed: 5\nslam:\n  filter:\n    particles: 7\n  motion:\n    srr: 0.2\n", "x");
  EXPECT_EQ(o.slam.particles, 7);
  EXPECT_DOUBLE_EQ(o.slam.motion.srr, 0.2);
  const slam::ParseError e = parse_error(
      "mission:\n  seed: 5\nslam:\n  filter:\n    particles: 7\n\n  # a comment\n    partcles: "
      "3\nrobot:\n  radius: 0.2\n");
  EXPECT_EQ(e.line(), 8u);
  EXPECT_EQ(e.field(), "filter.partcles");
  EXPECT_EQ(parse_error("slam:\n  filter:\n    particles: many\n").line(), 3u);
  EXPECT_EQ(parse_mission_options("slam: {filter: {particles: 9}}\n", "x").slam.particles, 9);
  EXPECT_EQ(parse_error("\nslam: {filter: {particle: 9}}\n").line(), 2u);
}

TEST(MissionConfig, YamlBlockTextPadsAndDedents) {
  const std::string text = "a:\n  b:\n    c: 1\n\n    d: 2\n  e: 3\n";
  EXPECT_EQ(yaml_block_text(text, 2, 4), "\n\nc: 1\n\nd: 2\n");
}

// config/mission/default.yaml documents the defaults: it must say exactly what the code does.
TEST(MissionConfig, ShippedDefaultsMatchTheCode) {
  const std::string path = std::string(LOOKAHEAD_SOURCE_DIR) + "/config/mission/default.yaml";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path << " missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), dump_mission_options(MissionOptions::defaults()))
      << "regenerate config/mission/default.yaml from "
         "dump_mission_options(MissionOptions::defaults())";
  EXPECT_NO_THROW(load_mission_options(path));
}

// The P-SLAM paper's RBPF (Chang et al. 2007: "the proposal distribution used in the RBPF is
// the action model as in FastSLAM") is one named choice in the slam section; nothing else moves.
TEST(MissionConfig, MotionModelProposalChangesOnlyTheProposal) {
  const MissionOptions o = parse_mission_options("slam:\n  proposal:\n    kind: motion_model\n", "m.yaml");
  EXPECT_EQ(o.slam.proposal.kind, slam::ProposalKind::kMotionModel);
  MissionOptions expected = MissionOptions::defaults();
  expected.slam.proposal.kind = slam::ProposalKind::kMotionModel;
  EXPECT_EQ(dump_mission_options(o), dump_mission_options(expected));
  EXPECT_NE(dump_mission_options(o), dump_mission_options(MissionOptions::defaults()));
}

// The escape switches of adopted behaviours are gone: a file that sets one is told so.
TEST(MissionConfig, RetiredKeysAreUnknown) {
  for (const char* key :
       {"squeeze_when_blocked", "progress_along_path", "gain_line_of_sight", "backtrack", "squeeze"}) {
    const slam::ParseError e = parse_error(std::string("mission:\n  ") + key + ": true\n");
    EXPECT_EQ(e.field(), std::string("mission.") + key);
    EXPECT_EQ(e.line(), 2u);
  }
}

// config/robot/pioneer3dx.yaml is the default robot: loading it changes nothing.
TEST(MissionConfig, PioneerRobotFileIsTheDefaultRobot) {
  const std::string path = std::string(LOOKAHEAD_SOURCE_DIR) + "/config/robot/pioneer3dx.yaml";
  const MissionOptions o = load_mission_options(path);
  EXPECT_EQ(dump_mission_options(o), dump_mission_options(MissionOptions::defaults()));
  EXPECT_DOUBLE_EQ(o.robot.radius, 0.25);
  EXPECT_DOUBLE_EQ(o.laser.max_range, 8.0);
}

// A robot file with garbage in it is refused with its path, the line and the value.
TEST(MissionConfig, GarbageRobotFileNamesPathLineAndValue) {
  const std::string path = ::testing::TempDir() + "garbage_robot.yaml";
  std::ofstream(path) << "robot:\n  radius: 0.2\n  max_speed: fast\n";
  try {
    load_mission_options(path, MissionOptions::defaults());
    FAIL() << "garbage accepted";
  } catch (const slam::ParseError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 3u);
    EXPECT_EQ(e.field(), "robot.max_speed");
    EXPECT_EQ(e.value(), "fast");
  }
}

// config/robot/p2explore.yaml is the KTH studies' robot, laid over any mission file.
TEST(MissionConfig, P2ExploreRobotFileIsTheStudiesRobot) {
  MissionOptions base = MissionOptions::defaults();
  base.strategy = "utility";
  const MissionOptions o =
      load_mission_options(std::string(LOOKAHEAD_SOURCE_DIR) + "/config/robot/p2explore.yaml", base);
  EXPECT_EQ(o.strategy, "utility");  // what the robot file leaves out stays
  EXPECT_DOUBLE_EQ(o.robot.radius, 0.1);
  EXPECT_DOUBLE_EQ(o.robot.max_speed, 0.2);
  EXPECT_NEAR(o.laser.fov, 2.0 * M_PI, 1e-6);
  EXPECT_DOUBLE_EQ(o.laser.max_range, 12.0);
  EXPECT_DOUBLE_EQ(o.slam.likelihood.max_range, 12.0);                      // harmonized
  EXPECT_DOUBLE_EQ(o.planner.costmap.robot_radius, 0.1 + o.safety_margin);  // harmonized
}

}  // namespace
}  // namespace lookahead::exploration

namespace lookahead::exploration {
namespace {

// P-SLAM options: garbage and impossible values name the file, line, key and value.
TEST(MissionConfig, LookaheadAndPredictionGarbageIsRejected) {
  slam::ParseError e = parse_error("lookahead:\n  latency: 1.0\n  skip_share: lots\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "lookahead.skip_share");
  EXPECT_EQ(e.value(), "lots");
  EXPECT_EQ(parse_error("lookahead:\n  similarity_threshold: 0.95\n").file(), "my.yaml");  // outside 0.4..0.7
  EXPECT_EQ(parse_error("lookahead:\n  targets_per_selection: 0\n").file(), "my.yaml");
  // The maze's skip rules (the mission defaults since the maze rule became the default).
  e = parse_error("lookahead:\n  predict_while_idle: sometimes\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "lookahead.predict_while_idle");
  EXPECT_EQ(e.value(), "sometimes");
  EXPECT_EQ(parse_error("lookahead:\n  repredict_after: 0\n").file(), "my.yaml");
  e = parse_error("lookahead:\n  skip: some\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "lookahead.skip");
  EXPECT_EQ(e.value(), "some");
  EXPECT_EQ(parse_mission_options("lookahead:\n  skip: far_side\n", "x").lookahead.skip, SkipVariant::kFarSide);
  EXPECT_EQ(MissionOptions::defaults().lookahead.skip, SkipVariant::kRegion);
  EXPECT_EQ(parse_error("lookahead:\n  skip_region_wall_gap: -0.5\n").file(), "my.yaml");
  EXPECT_EQ(parse_error("lookahead:\n  skip_region_radius: 0\n").file(),
            "my.yaml");  // a region has a reach
  EXPECT_EQ(parse_error("lookahead:\n  known_boundary: yes please\n").field(), "lookahead.known_boundary");
  e = parse_error("lookahead:\n  large_surroundings_diameter: wide\n");
  EXPECT_EQ(e.line(), 2u);
  EXPECT_EQ(e.field(), "lookahead.large_surroundings_diameter");
  EXPECT_EQ(e.value(), "wide");
  EXPECT_EQ(parse_error("lookahead:\n  large_surroundings_diameter: -14\n").file(), "my.yaml");  // out of range
  EXPECT_EQ(parse_error("lookahead:\n  large_max_conflict_share: 2\n").file(), "my.yaml");
  // The defaults keep the boundary and the slivers on; the share rule has no regions and ignores them.
  EXPECT_NO_THROW(parse_mission_options("lookahead:\n  skip: far_side\n  known_boundary: true\n", "x"));
  EXPECT_EQ(parse_error("lookahead:\n  skip_wall_slivers: maybe\n").value(), "maybe");
  // Slivers are regions of the region rule: without a region there are none.
  EXPECT_NO_THROW(parse_mission_options("lookahead:\n  skip: far_side\n  skip_wall_slivers: true\n", "x"));
  EXPECT_NO_THROW(parse_mission_options("lookahead:\n  skip_region_radius: 5\n  skip_wall_slivers: true\n", "x"));
  e = parse_error("slam:\n  prediction:\n    hit_ratio_threshold: high\n");
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(e.field(), "prediction.hit_ratio_threshold");
  EXPECT_EQ(parse_error("slam:\n  prediction:\n    hit_ratio_threshold: 2\n").file(), "my.yaml");
  const MissionOptions o = parse_mission_options("mission:\n  strategy: predictive\n", "x");
  EXPECT_TRUE(o.lookahead.enabled);  // the predictive strategy turns predictions on
}

}  // namespace
}  // namespace lookahead::exploration
