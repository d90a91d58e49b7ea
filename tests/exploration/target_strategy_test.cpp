// SPDX-License-Identifier: MIT
#include "lookahead/exploration/target_strategy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lookahead/exploration/travel_cost.hpp"

namespace lookahead::exploration {
namespace {

TEST(TargetStrategy, NearestPicksTheCheapestPath) {
  const std::vector<Candidate> c{{nullptr, 5.0, 100.0}, {nullptr, 2.0, 1.0}, {nullptr, 3.0, 50.0}};
  EXPECT_EQ(NearestFrontierStrategy().choose(c), 1u);
  EXPECT_FALSE(NearestFrontierStrategy().choose({}).has_value());
}

TEST(TargetStrategy, UtilityTradesGainAgainstCost) {
  const std::vector<Candidate> c{{nullptr, 5.0, 100.0}, {nullptr, 2.0, 1.0}, {nullptr, 3.0, 50.0}};
  EXPECT_EQ(UtilityStrategy(1.0).choose(c), 0u);  // 95 beats 47 and -1
  // With travel dominating: 100-150 = -50, 1-60 = -59, 50-90 = -40.
  EXPECT_EQ(UtilityStrategy(30.0).choose(c), 2u);
}

TEST(TargetStrategy, FactoryKnowsTheNames) {
  EXPECT_EQ(make_strategy("nearest")->name(), "nearest");
  EXPECT_EQ(make_strategy("utility")->name(), "utility");
  EXPECT_THROW(make_strategy("random"), std::invalid_argument);
}

// Oracle: on an open grid with one wall, Dijkstra distances equal the octile distance where
// the wall is not in the way, and go around it where it is.
TEST(TravelCost, OctileDistancesAndDetours) {
  const auto free = [](slam::CellIndex c) { return !(c.x == 5 && c.y <= 8); };  // wall x=5, y<=8
  const TravelCost t({0, 0}, {10, 10}, 1.0, {0, 0}, free);
  EXPECT_DOUBLE_EQ(t.at({0, 0}), 0.0);
  EXPECT_NEAR(t.at({3, 3}), 3 * std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(t.at({4, 0}), 4.0, 1e-5);
  EXPECT_GT(t.at({6, 0}), 10.0);  // around the wall's end at y = 9
  EXPECT_FALSE(t.reachable({5, 3}));
  EXPECT_FALSE(t.reachable({20, 20}));
  const auto path = t.path_to({6, 0});
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.front(), (slam::CellIndex{0, 0}));
  EXPECT_EQ(path.back(), (slam::CellIndex{6, 0}));
  for (const auto c : path) EXPECT_TRUE(free(c));
  EXPECT_TRUE(t.path_to({5, 3}).empty());

  // Stopping at targets: the same distances and paths for them, and the search ends early
  // (the far corner behind the wall is not settled when the targets are near).
  const TravelCost near({0, 0}, {10, 10}, 1.0, {0, 0}, free, {{3, 3}, {4, 0}});
  EXPECT_EQ(near.at({3, 3}), t.at({3, 3}));
  EXPECT_EQ(near.at({4, 0}), t.at({4, 0}));
  EXPECT_EQ(near.path_to({3, 3}), t.path_to({3, 3}));
  EXPECT_FALSE(near.reachable({10, 0}));
  const TravelCost far({0, 0}, {10, 10}, 1.0, {0, 0}, free, {{6, 0}, {5, 3}});  // one target is a wall
  EXPECT_EQ(far.at({6, 0}), t.at({6, 0}));
  EXPECT_EQ(far.path_to({6, 0}), path);
  EXPECT_FALSE(far.reachable({5, 3}));
}

}  // namespace
}  // namespace lookahead::exploration
