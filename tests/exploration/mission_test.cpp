// SPDX-License-Identifier: MIT
// Missions on small worlds: they finish, cover the reachable area, never collide, and end
// with the status that says why.
#include "lookahead/exploration/mission.hpp"

#include <gtest/gtest.h>

#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/mission_report.hpp"

namespace lookahead::exploration {
namespace {

MissionOptions quick(PoseSource source, const std::string& strategy = "nearest") {
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = source;
  o.strategy = strategy;
  o.slam.particles = 10;
  o.time_limit = 900;
  o.coverage_goal = 0.95;
  o.harmonize();
  return o;
}

GeneratedWorld small_office() {
  OfficeOptions o;
  o.rooms_per_side = 2;
  o.room_depth = 5.0;
  return make_office(o);
}

TEST(Mission, SmallOfficeReaches95PercentWithoutCollision) {
  for (const std::string strategy : {"nearest", "utility"}) {
    const GeneratedWorld w = small_office();
    Mission m(w.world, w.start, quick(PoseSource::kTruth, strategy));
    const MissionStatus s = m.run();
    EXPECT_EQ(s, MissionStatus::kCoverageReached) << strategy << ": " << to_string(s);
    EXPECT_GE(m.coverage(), 0.95) << strategy;
    EXPECT_EQ(m.statistics().collisions, 0) << strategy;
    const MissionSummary sum = summarize(m, "small office", 1.0);
    EXPECT_TRUE(sum.milestones[1].reached);
    EXPECT_GT(sum.quality.precision, 0.9);
  }
}

// The coverage goal is explored space: a predictive mission ends at it only once the robot
// has observed that much, whatever its look-ahead map predicts.
TEST(Mission, PredictiveMissionEndsOnExploredSpaceOnly) {
  const GeneratedWorld w = small_office();
  Mission m(w.world, w.start, quick(PoseSource::kTruth, "predictive-advantage"));
  EXPECT_EQ(m.run(), MissionStatus::kCoverageReached);
  EXPECT_GE(m.coverage(), 0.95);
  EXPECT_GE(m.coverage_curve().back().coverage_with_predictions, m.coverage());
  EXPECT_EQ(m.statistics().collisions, 0);
}

// The gain-rate strategies explore the office to the goal, with and without the predictor.
TEST(Mission, GainRateMissionsReachTheGoal) {
  const GeneratedWorld w = small_office();
  for (const char* strategy : {"rate", "predictive-rate"}) {
    SCOPED_TRACE(strategy);
    Mission m(w.world, w.start, quick(PoseSource::kTruth, strategy));
    EXPECT_EQ(m.run(), MissionStatus::kCoverageReached);
    EXPECT_GE(m.coverage(), 0.95);
    EXPECT_EQ(m.statistics().collisions, 0);
  }
}

TEST(Mission, SlamInTheLoopReaches95Percent) {
  const GeneratedWorld w = small_office();
  Mission m(w.world, w.start, quick(PoseSource::kSlam));
  EXPECT_EQ(m.run(), MissionStatus::kCoverageReached);
  EXPECT_EQ(m.statistics().collisions, 0);
  EXPECT_LT(std::hypot(m.truth().x - m.estimate().x, m.truth().y - m.estimate().y), 0.3);
}

// Explored means observed: with SLAM in the loop coverage counts what the laser saw from the
// true pose, not the SLAM map's cells (which lag the scans and may be shifted). While both
// robots turn in place at the start they see the same scans, so both count the same.
TEST(Mission, SlamCoverageCountsWhatTheLaserObserved) {
  const GeneratedWorld w = small_office();
  Mission slam(w.world, w.start, quick(PoseSource::kSlam));
  Mission truth(w.world, w.start, quick(PoseSource::kTruth));
  while (slam.time() < 4.0) slam.step(), truth.step();
  ASSERT_EQ(slam.truth().x, truth.truth().x);
  ASSERT_EQ(slam.truth().theta, truth.truth().theta);
  EXPECT_GT(slam.coverage(), 0.05);
  EXPECT_DOUBLE_EQ(slam.coverage(), truth.coverage());
  EXPECT_NE(&slam.observed_map(), &slam.map());
  EXPECT_EQ(&truth.observed_map(), &truth.map());
}

// A closed room: explored means observed, so once the laser has seen the room every sample
// of it counts, the cells beside the walls that the beam ends blur towards occupied included.
TEST(Mission, ClosedRoomIsObservedCompletely) {
  World world(120, 100, 0.05, {0, 0}, World::kOccupied);
  world.fill_rect({0.5, 0.5}, {5.5, 4.5}, World::kFree);
  MissionOptions o = quick(PoseSource::kTruth);
  o.coverage_goal = 1.0;
  Mission m(world, {3.0, 2.5, 0.0}, o);
  EXPECT_EQ(m.run(), MissionStatus::kCoverageReached);
  EXPECT_DOUBLE_EQ(m.coverage(), 1.0);
  EXPECT_LT(m.time(), 120.0);
}

// A room whose only way out is a 20 cm slit: the big hall behind it is seen through the
// slit, but the robot cannot get there, so it is no part of the area to explore and its
// frontier does not hold the mission once the room is seen.
TEST(Mission, FrontierBehindANarrowSlitDoesNotHoldTheMission) {
  World world(300, 100, 0.05, {0, 0}, World::kOccupied);
  world.fill_rect({0.5, 0.5}, {4.0, 4.5}, World::kFree);   // the robot's room
  world.fill_rect({4.0, 2.4}, {4.6, 2.6}, World::kFree);   // the slit
  world.fill_rect({4.6, 0.5}, {14.5, 4.5}, World::kFree);  // the hall
  MissionOptions o = quick(PoseSource::kTruth);
  o.coverage_goal = 1.0;
  Mission m(world, {2.0, 2.5, 0.0}, o);
  EXPECT_EQ(m.run(), MissionStatus::kCoverageReached);
  EXPECT_LT(m.time(), 120.0);
  EXPECT_NEAR(m.reachable().area_m2, 3.5 * 4.0, 0.5);
  EXPECT_EQ(m.statistics().collisions, 0);
}

// A room whose only way out is a 0.35 m door: the 0.1 m robot fits (7.5 cm each side), but the
// planning margin (0.08 m) closes it. The path planned before the door's jambs were seen is
// kept while the body fits, or the squeeze, the last resort, takes the robot through.
TEST(Mission, DoorOnlyTheBodyFitsIsPassed) {
  World world(300, 100, 0.05, {0, 0}, World::kOccupied);
  world.fill_rect({0.5, 0.5}, {4.0, 4.5}, World::kFree);    // the robot's room
  world.fill_rect({4.0, 2.30}, {4.6, 2.65}, World::kFree);  // the door, 0.6 m deep
  world.fill_rect({4.6, 0.5}, {14.5, 4.5}, World::kFree);   // the hall
  MissionOptions o = quick(PoseSource::kTruth);
  o.robot.radius = 0.1;
  o.harmonize();
  Mission m(world, {2.0, 2.5, 0.0}, o);
  const MissionStatus s = m.run();
  EXPECT_EQ(m.statistics().collisions, 0);
  EXPECT_EQ(s, MissionStatus::kCoverageReached) << to_string(s);
  EXPECT_GE(m.statistics().squeezes + m.statistics().kept_paths, 1);
  EXPECT_GT(m.truth().x, 4.6);  // in the hall
}

TEST(Mission, RejectsAStartInAWall) {
  const GeneratedWorld w = small_office();
  EXPECT_THROW(Mission(w.world, {0.0, 0.0, 0.0}, quick(PoseSource::kTruth)), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::exploration
