// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <random>

namespace lookahead::slam {
namespace {

TEST(OccupancyGrid, UnknownEverywhereAtFirst) {
  const OccupancyGrid g;
  EXPECT_FALSE(g.is_known({0, 0}));
  EXPECT_FALSE(g.is_known({-1000, 5000}));
  EXPECT_DOUBLE_EQ(g.probability({3, 3}), 0.5);
  EXPECT_EQ(g.dist2({3, 3}), GridTile::kFar);
  CellIndex lo, hi;
  EXPECT_FALSE(g.known_bounds(lo, hi));
}

TEST(OccupancyGrid, CellAtFloorsNegativeCoordinates) {
  const OccupancyGrid g;
  EXPECT_EQ(g.cell_at(0.01, 0.01), (CellIndex{0, 0}));
  EXPECT_EQ(g.cell_at(-0.01, -0.06), (CellIndex{-1, -2}));
}

TEST(OccupancyGrid, HitMakesObstacleWithZeroDistance) {
  OccupancyGrid g;
  g.add_log_odds({-40, 7}, g.fixed_hit());
  EXPECT_TRUE(g.is_obstacle({-40, 7}));
  EXPECT_EQ(g.dist2({-40, 7}), 0);
  EXPECT_EQ(g.dist2({-38, 8}), 5);
  EXPECT_GT(g.probability({-40, 7}), 0.69);
}

TEST(OccupancyGrid, LogOddsAreClamped) {
  OccupancyGrid g;
  for (int i = 0; i < 100; ++i) g.add_log_odds({1, 1}, g.fixed_miss());
  EXPECT_NEAR(g.probability({1, 1}), 1.0 / (1.0 + std::exp(2.0)), 1e-3);
}

// Oracle: after random hits and misses, every distance equals the brute-force nearest
// obstacle distance (clipped at the field radius).
TEST(OccupancyGrid, DistanceFieldMatchesBruteForce) {
  OccupancyGrid g;
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> cell(-20, 20);
  std::bernoulli_distribution hit(0.5);
  for (int i = 0; i < 3000; ++i) {
    const CellIndex c{cell(rng), cell(rng)};
    g.add_log_odds(c, hit(rng) ? g.fixed_hit() : 3 * g.fixed_miss());
  }
  const int r = g.distance_radius_cells();
  for (int y = -25; y <= 25; ++y) {
    for (int x = -25; x <= 25; ++x) {
      int best = GridTile::kFar;
      for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
          const int d2 = dx * dx + dy * dy;
          if (d2 < r * r && d2 < best && g.is_obstacle({x + dx, y + dy})) best = d2;
        }
      }
      ASSERT_EQ(g.dist2({x, y}), best) << "cell " << x << "," << y;
    }
  }
}

TEST(OccupancyGrid, CopySharesTilesUntilOneIsWritten) {
  OccupancyGrid a;
  for (int x = 0; x < 200; x += 3) a.add_log_odds({x, x / 2}, a.fixed_hit());
  OccupancyGrid b = a;
  const std::size_t tiles = a.tile_count();
  ASSERT_GT(tiles, 5u);
  EXPECT_EQ(a.tiles_shared_with(b), tiles);
  b.add_log_odds({12, 20}, b.fixed_miss());  // in an existing tile, far from obstacles
  EXPECT_EQ(a.tiles_shared_with(b), tiles - 1);
  EXPECT_FALSE(a.is_known({12, 20}));  // the original did not change
  EXPECT_TRUE(b.is_known({12, 20}));
}

TEST(OccupancyGrid, RejectsImpossibleOptions) {
  GridOptions o;
  o.resolution = 0;
  EXPECT_THROW(OccupancyGrid{o}, std::invalid_argument);
  o = {};
  o.obstacle_on = -1;
  EXPECT_THROW(OccupancyGrid{o}, std::invalid_argument);
  o = {};
  o.distance_field_radius = 5.0;
  EXPECT_THROW(OccupancyGrid{o}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam
