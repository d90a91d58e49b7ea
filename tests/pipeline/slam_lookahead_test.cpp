// SPDX-License-Identifier: MIT
#include "lookahead/pipeline/slam_lookahead.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::pipeline {
namespace {

TEST(FrontierAhead, FindsTheNearestFrontierInTheHeadingCone) {
  slam::OccupancyGrid map;
  for (double y = -2; y < 2; y += 0.05)
    for (double x = -3; x < 3; x += 0.05) map.add_log_odds(map.cell_at(x, y), -1000);
  const auto ahead = frontier_ahead(map, {0, 0, 0}, 8.0, 0.5);
  ASSERT_TRUE(ahead.has_value());
  EXPECT_NEAR(ahead->first, 3.0, 0.1);  // the free area ends at x = 3 ahead
  EXPECT_NEAR(ahead->second, 0.0, 1.6);
  const auto behind = frontier_ahead(map, {0, 0, M_PI}, 8.0, 0.5);
  ASSERT_TRUE(behind.has_value());
  EXPECT_NEAR(behind->first, -3.0, 0.1);
  EXPECT_FALSE(frontier_ahead(map, {0, 0, 0}, 2.0, 0.5).has_value());  // out of range
}

TEST(FrontierAhead, CandidatesComeNearestFirstAndSpacedApart) {
  slam::OccupancyGrid map;
  for (double y = -2; y < 2; y += 0.05)
    for (double x = -3; x < 3; x += 0.05) map.add_log_odds(map.cell_at(x, y), -1000);
  const auto all = frontiers_ahead(map, {0, 0, 0}, 8.0, 1.2, 6, 0.5);
  ASSERT_EQ(all.size(), 6u);
  double last = 0.0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double d = std::hypot(all[i].first, all[i].second);
    EXPECT_GE(d, last - 1e-9);
    last = d;
    EXPECT_LE(std::abs(std::atan2(all[i].second, all[i].first)), 1.2);
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_GE(std::hypot(all[i].first - all[j].first, all[i].second - all[j].second), 0.5);
  }
  EXPECT_EQ(all.front(), *frontier_ahead(map, {0, 0, 0}, 8.0, 1.2));
}

}  // namespace
}  // namespace lookahead::pipeline
