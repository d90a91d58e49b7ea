// SPDX-License-Identifier: MIT
// The idle predictor tries a frontier spot again only after `wait` and once the known cells
// of its surroundings grew by `growth`: a registration of unchanged surroundings repeats
// its answer.
#include "lookahead/exploration/prediction_attempts.hpp"

#include <gtest/gtest.h>

#include "hand_made_grid.hpp"

namespace lookahead::exploration {
namespace {

TEST(PredictionAttempts, ASpotIsTriedAgainOnlyOnceItsSurroundingsGrew) {
  slam::OccupancyGrid map;  // 5 cm cells: 2 m x 2 m known around the spot at (1, 1)
  testing::add_rect(map, 0, 0, 39, 39, 3 * map.fixed_miss());
  PredictionAttempts tried({1.0, 10.0, 10.0, 0.1});
  EXPECT_FALSE(tried.tried_lately(map, 1.0, 1.0, 0.0));
  tried.add(map, 1.0, 1.0, 0.0);
  EXPECT_TRUE(tried.tried_lately(map, 1.0, 1.0, 5.0));          // too soon
  EXPECT_TRUE(tried.tried_lately(map, 1.5, 1.5, 20.0));         // the same spot, nothing new around it
  EXPECT_FALSE(tried.tried_lately(map, 5.0, 1.0, 5.0));         // another spot
  testing::add_rect(map, 40, 0, 59, 39, 3 * map.fixed_miss());  // +50 % known
  EXPECT_TRUE(tried.tried_lately(map, 1.0, 1.0, 5.0));          // grown, but still too soon
  EXPECT_FALSE(tried.tried_lately(map, 1.0, 1.0, 20.0));        // grown and old enough
  tried.add(map, 1.0, 1.0, 20.0);                               // a new try replaces the old one
  EXPECT_EQ(tried.size(), 1u);
  EXPECT_TRUE(tried.tried_lately(map, 1.0, 1.0, 40.0));
}

TEST(PredictionAttempts, WithoutAGrowthRuleTheWaitAloneDecides) {
  slam::OccupancyGrid map;
  PredictionAttempts tried({1.0, 10.0, 10.0, 0.0});
  tried.add(map, 0.0, 0.0, 0.0);
  EXPECT_TRUE(tried.tried_lately(map, 0.0, 0.0, 9.9));
  EXPECT_FALSE(tried.tried_lately(map, 0.0, 0.0, 10.0));
}

}  // namespace
}  // namespace lookahead::exploration
