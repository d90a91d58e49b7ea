// SPDX-License-Identifier: MIT
// Distance advantage: a frontier the robot is nearer to than any other frontier is taken
// before nearer ones that other frontiers will bring the robot back to.
#include "lookahead/exploration/distance_advantage_strategy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "frontier_goal.hpp"

namespace lookahead::exploration {
namespace {

TEST(DistanceAdvantage, IsTheGapToTheNearestOtherFrontierMinusTheTravelCost) {
  const FrontierCluster a = goal_at(2, 0), b = goal_at(3, 0), c = goal_at(-8, 0);
  const std::vector<Candidate> cands{{&a, 2.0, 0.0}, {&b, 3.0, 0.0}, {&c, 8.0, 0.0}};
  EXPECT_DOUBLE_EQ(distance_advantage(cands, 0), 1.0 - 2.0);
  EXPECT_DOUBLE_EQ(distance_advantage(cands, 1), 1.0 - 3.0);
  EXPECT_DOUBLE_EQ(distance_advantage(cands, 2), 10.0 - 8.0);
  const std::vector<Candidate> alone{{&a, 2.0, 0.0}};
  EXPECT_EQ(distance_advantage(alone, 0), std::numeric_limits<double>::infinity());
}

TEST(DistanceAdvantage, TakesTheRobotsOwnFrontierBeforeNearerSharedOnes) {
  const FrontierCluster a = goal_at(2, 0), b = goal_at(3, 0), c = goal_at(-8, 0);
  const std::vector<Candidate> cands{{&a, 2.0, 0.0}, {&b, 3.0, 0.0}, {&c, 8.0, 0.0}};
  EXPECT_EQ(DistanceAdvantageStrategy().choose(cands), std::optional<std::size_t>(2));
}

TEST(DistanceAdvantage, WithoutAnAdvantageAnywhereIsNearest) {
  const FrontierCluster a = goal_at(5, 0), b = goal_at(5.5, 0), c = goal_at(6, 0);
  const std::vector<Candidate> cands{{&a, 5.0, 0.0}, {&b, 5.5, 0.0}, {&c, 6.0, 0.0}};
  EXPECT_EQ(DistanceAdvantageStrategy().choose(cands), std::optional<std::size_t>(0));
  EXPECT_FALSE(DistanceAdvantageStrategy().choose({}).has_value());
}

TEST(DistanceAdvantage, TheFactoryKnowsItWithAndWithoutPrediction) {
  EXPECT_EQ(make_strategy("advantage")->name(), "advantage");
  EXPECT_FALSE(make_strategy("advantage")->uses_prediction());
  EXPECT_EQ(make_strategy("predictive-advantage")->name(), "predictive-advantage");
  EXPECT_TRUE(make_strategy("predictive-advantage")->uses_prediction());
}

}  // namespace
}  // namespace lookahead::exploration
