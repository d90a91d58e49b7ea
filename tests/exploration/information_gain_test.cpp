// SPDX-License-Identifier: MIT
#include "lookahead/exploration/information_gain.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::exploration {
namespace {

// Marks a cell occupied beyond doubt (several hits, as a wall seen many times).
void wall(slam::OccupancyGrid& g, slam::CellIndex c) {
  for (int k = 0; k < 10; ++k) g.add_log_odds(c, g.fixed_hit());
}

TEST(InformationGain, UnknownDiscAreaWhenNothingIsKnown) {
  const slam::OccupancyGrid g;
  EXPECT_NEAR(information_gain(g, 0, 0, 2.0), M_PI * 4.0, 0.3);
  EXPECT_NEAR(visible_information_gain(g, 0, 0, 2.0), M_PI * 4.0, 0.3);
  EXPECT_NEAR(visible_information_gain(g, 0, 0, 12.0), M_PI * 144.0, 0.02 * M_PI * 144.0);
}

TEST(InformationGain, KnownHalfPlaneHalvesTheGain) {
  slam::OccupancyGrid g;
  for (int y = -60; y <= 60; ++y)
    for (int x = 0; x <= 60; ++x) g.add_log_odds({x, y}, g.fixed_miss());
  const double full = information_gain(slam::OccupancyGrid{}, 0.0, 0.0, 2.0);
  EXPECT_NEAR(information_gain(g, 0.0, 0.0, 2.0), full / 2, full * 0.05);
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 2.0), full / 2, full * 0.05);
  // Cells a predictor claims count as known too.
  const auto predicted = [](slam::CellIndex c) { return c.x < 0; };
  EXPECT_NEAR(information_gain(g, 0.0, 0.0, 2.0, predicted), 0.0, 1e-9);
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 2.0, predicted), 0.0, 1e-9);
}

TEST(InformationGain, CellsACallerNamesOccludeLikeWalls) {
  // Unknown space seen from the origin with a 5 m range: the open disc, until a predicted
  // wall ring at 2 m stops the rays and leaves the inside of the ring (predicted walls in
  // the gain of predictive-rate).
  const slam::OccupancyGrid g;
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 5.0), M_PI * 25.0, 0.02 * M_PI * 25.0);
  const auto ring = [&](slam::CellIndex c) {
    double x, y;
    g.cell_center(c, x, y);
    const double r = std::hypot(x, y);
    return r >= 2.0 && r < 2.1;
  };
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 5.0, nullptr, ring), M_PI * 4.0, 0.05 * M_PI * 4.0);
}

TEST(InformationGain, AWallHidesTheUnknownBehindIt) {
  // A wall along x = 1 m (cells of 5 cm) in unknown space: the disc of 2 m loses its
  // segment beyond the wall, R^2 acos(d/R) - d sqrt(R^2 - d^2) = 2.457 m^2 for d = 1, R = 2.
  slam::OccupancyGrid g;
  for (int y = -60; y <= 60; ++y) wall(g, {20, y});
  const double disc = information_gain(g, 0.0, 0.0, 2.0);
  const double segment = 4.0 * std::acos(0.5) - std::sqrt(3.0);
  const double wall_area = 0.05 * 2 * std::sqrt(3.0);
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 2.0), 4 * M_PI - segment - wall_area, 0.25);
  EXPECT_GT(disc - visible_information_gain(g, 0.0, 0.0, 2.0), 2.0);
}

TEST(InformationGain, NothingIsVisibleFromInsideAClosedRoom) {
  // A mapped 2 m x 2 m room (free inside, walls around) in an unknown world: the disc counts
  // the outside, line of sight does not.
  slam::OccupancyGrid g;
  for (int y = -20; y <= 20; ++y)
    for (int x = -20; x <= 20; ++x) {
      const bool edge = std::abs(x) == 20 || std::abs(y) == 20;
      if (edge)
        wall(g, {x, y});
      else
        g.add_log_odds({x, y}, g.fixed_miss());
    }
  EXPECT_GT(information_gain(g, 0.0, 0.0, 4.0), 30.0);
  EXPECT_NEAR(visible_information_gain(g, 0.0, 0.0, 4.0), 0.0, 1e-9);
  // A one-cell gap in the wall lets a wedge through.
  g.add_log_odds({20, 0}, -20 * g.fixed_hit());
  EXPECT_GT(visible_information_gain(g, 0.0, 0.0, 4.0), 0.05);
}

}  // namespace
}  // namespace lookahead::exploration
