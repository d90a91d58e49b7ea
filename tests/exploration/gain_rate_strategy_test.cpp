// SPDX-License-Identifier: MIT
// Gain rate: the most unknown area per metre of travel, with a fixed offset on every path;
// with prediction, the gain is priced through the look-ahead map.
#include "lookahead/exploration/gain_rate_strategy.hpp"

#include <gtest/gtest.h>

#include "frontier_goal.hpp"
#include "lookahead/exploration/distance_advantage_strategy.hpp"

namespace lookahead::exploration {
namespace {

TEST(GainRate, IsTheGainPerMetreOfTheTripAndTheWayBack) {
  const FrontierCluster a = goal_at(1, 0);
  // The nearest frontier itself: its path and the offset.
  EXPECT_DOUBLE_EQ(gain_rate({&a, 6.0, 30.0}, 4.0, 6.0), 3.0);
  EXPECT_DOUBLE_EQ(gain_rate({&a, 0.0, 30.0}, 4.0, 0.0), 7.5);
  // 6 m beyond a frontier 2 m away: the 4 m past it are driven again to come back.
  EXPECT_DOUBLE_EQ(gain_rate({&a, 6.0, 28.0}, 4.0, 2.0), 2.0);
}

// Rooms a few metres away against the corridor's far end with a little more gain per metre
// of the way there (the numbers of a KTH office floor): the rooms are left for the far end
// only if the way back to them is not counted.
TEST(GainRate, FinishesTheRoomsNearbyBeforeTheFarEndOfTheCorridor) {
  const FrontierCluster room = goal_at(5, 0), other_room = goal_at(7.5, 0), far = goal_at(25, 0);
  const std::vector<Candidate> cands{{&room, 5.0, 92.0}, {&other_room, 7.5, 113.0}, {&far, 24.9, 318.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(0));
  // Per metre of the way there alone, the far end wins.
  EXPECT_GT(318.0 / (24.9 + 4.0), 92.0 / (5.0 + 4.0));
}

// Two slivers side by side: either can be taken later on the way past the other, so
// neither is the robot's own and the rate alone decides.
TEST(GainRate, TakesARoomAFewMetresOnBeforeASliverAtArmsLength) {
  const FrontierCluster sliver = goal_at(0.1, 0), beside = goal_at(0.15, 0), room = goal_at(6, 0);
  const std::vector<Candidate> cands{{&sliver, 0.1, 2.0}, {&beside, 0.15, 2.0}, {&room, 6.0, 40.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(2));
  // Nearest would take the sliver; so does a rate with no offset, where a tenth of a metre
  // divides the sliver's gain by almost nothing.
  EXPECT_EQ(GainRateStrategy(0.01, false).choose(cands), std::optional<std::size_t>(0));
}

TEST(GainRate, DoesNotCrossTheBuildingForALittleMoreGain) {
  const FrontierCluster near = goal_at(3, 0), far = goal_at(60, 0);
  const std::vector<Candidate> cands{{&near, 3.0, 50.0}, {&far, 60.0, 120.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(0));
}

// A closet 2 m beside the robot and, 10 m down the corridor, two rooms with twenty times its
// gain: the rate alone goes down the corridor and leaves the closet for a trip back at the
// end; nothing else lies near the closet, so it comes first.
TEST(GainRate, LeavesNoFrontierBehindThatNoOtherTargetPasses) {
  const FrontierCluster closet = goal_at(-2, 0), room = goal_at(10, 0), next_room = goal_at(11, 0);
  const std::vector<Candidate> cands{{&closet, 2.0, 5.0}, {&room, 10.0, 100.0}, {&next_room, 11.0, 100.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(0));
  EXPECT_GT(distance_advantage(cands, 0), 0.0);
  EXPECT_LT(distance_advantage(cands, 1), 0.0);
  // By rate alone the rooms win by far.
  EXPECT_GT(gain_rate(cands[1], 4.0, 2.0), 5 * gain_rate(cands[0], 4.0, 2.0));
}

// Two frontiers the robot is nearer to than anything else: the rate picks between them.
TEST(GainRate, RanksTheRobotsOwnFrontiersByRate) {
  const FrontierCluster left = goal_at(-3, 0), right = goal_at(4, 0), far = goal_at(20, 0), far_next = goal_at(21, 0);
  const std::vector<Candidate> cands{
      {&left, 3.0, 6.0}, {&right, 4.0, 60.0}, {&far, 20.0, 500.0}, {&far_next, 21.0, 500.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(1));
}

TEST(GainRate, WithNoGainAnywhereTakesTheNearest) {
  const FrontierCluster a = goal_at(5, 0), b = goal_at(2, 0), c = goal_at(9, 0);
  const std::vector<Candidate> cands{{&a, 5.0, 0.0}, {&b, 2.0, 0.0}, {&c, 9.0, 0.0}};
  EXPECT_EQ(GainRateStrategy(4.0, false).choose(cands), std::optional<std::size_t>(1));
  EXPECT_FALSE(GainRateStrategy(4.0, false).choose({}).has_value());
}

TEST(GainRate, TheFactoryKnowsItWithAndWithoutPrediction) {
  EXPECT_EQ(make_strategy("rate")->name(), "rate");
  EXPECT_EQ(make_strategy("rate")->prediction_use(), PredictionUse::kNone);
  EXPECT_FALSE(make_strategy("rate")->uses_prediction());
  EXPECT_EQ(make_strategy("predictive-rate")->name(), "predictive-rate");
  EXPECT_EQ(make_strategy("predictive-rate")->prediction_use(), PredictionUse::kOccludingGain);
  EXPECT_EQ(make_strategy("predictive")->prediction_use(), PredictionUse::kSkip);
}

TEST(GainRate, TheOffsetReachesTheStrategy) {
  const FrontierCluster sliver = goal_at(0.1, 0), beside = goal_at(0.15, 0), room = goal_at(6, 0);
  const std::vector<Candidate> cands{{&sliver, 0.1, 2.0}, {&beside, 0.15, 2.0}, {&room, 6.0, 40.0}};
  EXPECT_EQ(make_strategy("rate", 1.0, 0.8, 4.0)->choose(cands), std::optional<std::size_t>(2));
  EXPECT_EQ(make_strategy("rate", 1.0, 0.8, 0.01)->choose(cands), std::optional<std::size_t>(0));
}

}  // namespace
}  // namespace lookahead::exploration
