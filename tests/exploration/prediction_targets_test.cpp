// SPDX-License-Identifier: MIT
// Which frontiers look-ahead mapping predicts: at a selection the chosen goal and its nearest
// neighbours; while the predictor is idle the nearest frontiers the look-ahead map does not
// cover and that were not tried lately (and again once the memory of a try expires).
#include <gtest/gtest.h>

#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/mission_report.hpp"
#include "lookahead/exploration/prediction_targets.hpp"

namespace lookahead::exploration {
namespace {

FrontierCluster goal_at(double x, double y) {
  FrontierCluster f;
  f.has_goal = true;
  f.goal_x = x;
  f.goal_y = y;
  return f;
}

TEST(PredictionTargets, ASelectionPredictsItsGoalThenTheNearestOtherFrontiers) {
  const std::vector<FrontierCluster> clusters{goal_at(9, 0), goal_at(2, 0), goal_at(5.5, 0), goal_at(5, 0),
                                              goal_at(1, 0)};
  const TargetList t = selection_targets(clusters, 5, 0, {0, 0, 0}, 3);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], std::make_pair(5.0, 0.0));  // the goal first
  EXPECT_EQ(t[1], std::make_pair(1.0, 0.0));  // then nearest to the robot
  EXPECT_EQ(t[2], std::make_pair(2.0, 0.0));  // (5.5 is the goal's own frontier: within 1 m)
}

// A frontier along x = 0 facing +x, its goal at (-0.5, 0.5).
FrontierCluster wall_frontier(slam::OccupancyGrid& map, int x0) {
  FrontierCluster f = goal_at(x0 * 0.05 - 0.5, 0.5);
  for (int y = 0; y < 20; ++y) {
    map.add_log_odds({x0, y}, -1000);
    map.add_log_odds({x0 - 1, y}, -1000);
    f.cells.push_back({x0, y});
  }
  return f;
}

TEST(PredictionTargets, AnIdlePredictorTakesTheNearestFrontiersNeitherCoveredNorTriedLately) {
  slam::OccupancyGrid map;
  const std::vector<FrontierCluster> clusters{wall_frontier(map, 0), wall_frontier(map, 100), wall_frontier(map, 200),
                                              wall_frontier(map, 300)};
  PredictedMap predicted;
  slam::HypothesisMap h;  // predicts the far side of the frontier at x = 0, its ends included
  for (int y = -1; y <= 20; ++y)
    for (int x = 0; x <= 10; ++x) h.grid.add_log_odds({x, y}, -1000);
  h.similarity = 0.8;
  predicted.add(h);
  GoalBlacklist tried({1.0, 10.0, 1000});
  tried.add(clusters[1].goal_x, clusters[1].goal_y, 0.0);  // tried at t = 0
  const SkipRule rule;
  const slam::Pose2 robot{0, 0, 0};
  TargetList t = unpredicted_frontier_targets(clusters, map, predicted, rule, 1.0, tried, 5.0, robot, 4);
  ASSERT_EQ(t.size(), 2u);  // 0 is covered, 1 was tried 5 s ago
  EXPECT_DOUBLE_EQ(t[0].first, clusters[2].goal_x);
  EXPECT_DOUBLE_EQ(t[1].first, clusters[3].goal_x);
  t = unpredicted_frontier_targets(clusters, map, predicted, rule, 1.0, tried, 11.0, robot, 1);
  ASSERT_EQ(t.size(), 1u);  // the try expired: the nearest open one again, one at most
  EXPECT_DOUBLE_EQ(t[0].first, clusters[1].goal_x);
}

TEST(PredictionTargets, AMissionPredictingWhileIdleMakesMoreRequests) {
  const GeneratedWorld maze = make_pslam_maze({});
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.strategy = "predictive";
  o.time_limit = 120;
  o.harmonize();
  Mission plain(maze.world, maze.start, o);
  plain.run();
  o.lookahead.predict_while_idle = true;
  Mission idle(maze.world, maze.start, o);
  idle.run();
  EXPECT_GT(summarize_predictions(idle).requests, summarize_predictions(plain).requests + 10);
  EXPECT_EQ(idle.statistics().collisions, 0);
}

}  // namespace
}  // namespace lookahead::exploration
