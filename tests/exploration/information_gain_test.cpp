// SPDX-License-Identifier: MIT
#include "lookahead/exploration/information_gain.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::exploration {
namespace {

TEST(InformationGain, UnknownDiscAreaWhenNothingIsKnown) {
  const slam::OccupancyGrid g;
  EXPECT_NEAR(information_gain(g, 0, 0, 2.0), M_PI * 4.0, 0.3);
}

TEST(InformationGain, KnownHalfPlaneHalvesTheGain) {
  slam::OccupancyGrid g;
  for (int y = -60; y <= 60; ++y)
    for (int x = 0; x <= 60; ++x) g.add_log_odds({x, y}, g.fixed_miss());
  const double full = information_gain(slam::OccupancyGrid{}, 0.0, 0.0, 2.0);
  EXPECT_NEAR(information_gain(g, 0.0, 0.0, 2.0), full / 2, full * 0.05);
  // Cells a predictor claims count as known too.
  const auto predicted = [](slam::CellIndex c) { return c.x < 0; };
  EXPECT_NEAR(information_gain(g, 0.0, 0.0, 2.0, predicted), 0.0, 1e-9);
}

}  // namespace
}  // namespace lookahead::exploration
