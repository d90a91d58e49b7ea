// SPDX-License-Identifier: MIT
// Which frontiers look-ahead mapping predicts: at a selection the chosen goal and its nearest
// neighbours; while the predictor is idle the nearest frontiers the look-ahead map does not
// cover and that were not tried lately (and again once the memory of a try expires).
#include "lookahead/exploration/prediction_targets.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "frontier_goal.hpp"
#include "hand_made_grid.hpp"
#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/mission_report.hpp"

namespace lookahead::exploration {
namespace {

TEST(PredictionTargets, ASelectionPredictsItsGoalThenTheNearestOtherFrontiers) {
  const std::vector<FrontierCluster> clusters{goal_at(9, 0), goal_at(2, 0), goal_at(5.5, 0), goal_at(5, 0),
                                              goal_at(1, 0)};
  const TargetList t = selection_targets(clusters, 5, 0, {0, 0, 0}, 3);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0], std::make_pair(5.0, 0.0));  // the goal first
  EXPECT_EQ(t[1], std::make_pair(1.0, 0.0));  // then nearest to the robot
  EXPECT_EQ(t[2], std::make_pair(2.0, 0.0));  // (5.5 is the goal's own frontier: within 1 m)
}

// Two frontiers share a goal spot and only one is predicted: dropping the goal would have the
// next selection choose the same spot for the other one, at every check.
TEST(PredictionTargets, AGoalIsDroppedOnlyWhenEveryFrontierAtItsSpotIsPredicted) {
  std::vector<FrontierCluster> clusters{goal_at(5, 0), goal_at(5.3, 0.2), goal_at(9, 0)};
  clusters[0].centroid_x = 1;  // marks the predicted one
  const auto covered = [](const FrontierCluster& f) { return f.centroid_x == 1; };
  EXPECT_FALSE(goal_serves_only_predicted(clusters, 5, 0, 1.0, covered));
  clusters[1].centroid_x = 1;
  EXPECT_TRUE(goal_serves_only_predicted(clusters, 5, 0, 1.0, covered));
  EXPECT_FALSE(goal_serves_only_predicted(clusters, 9, 0, 1.0, covered));   // its frontier is open
  EXPECT_FALSE(goal_serves_only_predicted(clusters, 20, 0, 1.0, covered));  // no frontier there
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
  PredictionAttempts tried({1.0, 10.0, 10.0, 0.0});
  tried.add(map, clusters[1].goal_x, clusters[1].goal_y, 0.0);  // tried at t = 0
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

// A 4 m x 3 m walled room at 5 cm cells; an inner wall at y = 1 m runs from the left wall
// to x = 3 m. The robot at (0.5, 0.5); goal A at (0.5, 1.5) is 1 m away in a straight line
// but over 5 m round the wall's end; goal B at (2.5, 0.5) is 2 m away either way; goal C
// at (-1, 0.5) lies outside the room, where no path leads.
struct WalledRoom {
  slam::OccupancyGrid map;
  planner::Costmap costmap;
  std::vector<FrontierCluster> clusters{goal_at(0.5, 1.5), goal_at(2.5, 0.5), goal_at(-1.0, 0.5)};
  slam::Pose2 robot{0.5, 0.5, 0.0};
  WalledRoom() {
    testing::add_rect(map, 0, 0, 79, 59, 3 * map.fixed_miss());
    testing::add_rect(map, -1, -1, 80, -1, 6 * map.fixed_hit());
    testing::add_rect(map, -1, 60, 80, 60, 6 * map.fixed_hit());
    testing::add_rect(map, -1, -1, -1, 60, 6 * map.fixed_hit());
    testing::add_rect(map, 80, -1, 80, 60, 6 * map.fixed_hit());
    testing::add_rect(map, 0, 20, 59, 20, 9 * map.fixed_hit());
    planner::CostmapOptions o;
    o.robot_radius = 0.1;
    costmap = planner::Costmap(map, o);
  }
};

TEST(PredictionTargets, TheChosenGoalFirstThenTheNearestInAStraightLine) {
  const WalledRoom room;
  TargetList t = selection_targets(room.clusters, 3.5, 2.5, room.robot, 4);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0], std::make_pair(3.5, 2.5));  // the chosen goal first
  EXPECT_EQ(t[1], std::make_pair(0.5, 1.5));
  const PredictedMap nothing_predicted;
  const PredictionAttempts tried;
  t = unpredicted_frontier_targets(room.clusters, room.map, nothing_predicted, SkipRule{}, 1.0, tried, 0.0, room.robot,
                                   1);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0], std::make_pair(0.5, 1.5));
}

TEST(PredictionTargets, AMissionPredictingWhileIdleMakesMoreRequests) {
  const GeneratedWorld maze = make_pslam_maze({});
  MissionOptions o = MissionOptions::defaults();
  o.pose_source = PoseSource::kTruth;
  o.strategy = "predictive";
  o.time_limit = 120;
  o.lookahead.predict_while_idle = false;  // on by default
  o.harmonize();
  Mission plain(maze.world, maze.start, o);
  plain.run();
  o.lookahead.predict_while_idle = true;
  Mission idle(maze.world, maze.start, o);
  idle.run();
  EXPECT_GT(summarize_predictions(idle).requests, summarize_predictions(plain).requests + 10);
  EXPECT_EQ(idle.statistics().collisions, 0);
}

// A wall gap closes a region only where the robot cannot pass: the mission's rule takes the
// options' 0.5 m for the Pioneer (0.5 m across) and the robot's diameter for a smaller robot
// (a 0.2 m robot passes 0.4 m doors; closed as gaps, they would make rooms behind doors wall
// slivers, skipped unexplored).
TEST(PredictionTargets, WallGapsAreNoWiderThanTheRobot) {
  const GeneratedWorld maze = make_pslam_maze({});
  MissionOptions o = MissionOptions::defaults();
  o.strategy = "predictive";
  o.harmonize();
  EXPECT_DOUBLE_EQ(Mission(maze.world, maze.start, o).skip_rule().wall_gap, 0.5);
  ASSERT_TRUE(Mission(maze.world, maze.start, o).skip_rule().boundary.has_value());  // the world's extent
  o.robot.radius = 0.1;
  o.harmonize();
  EXPECT_DOUBLE_EQ(Mission(maze.world, maze.start, o).skip_rule().wall_gap, 0.2);
}

}  // namespace
}  // namespace lookahead::exploration
