// SPDX-License-Identifier: MIT
#include "lookahead/planner/costmap.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "test_worlds.hpp"

namespace lookahead::planner {
namespace {

using slam::CellIndex;
using slam::OccupancyGrid;
using testing::fill;
using testing::set_occupied;

TEST(Costmap, EmptyGridGivesEmptyCostmap) {
  const OccupancyGrid g;
  const Costmap c(g, {});
  EXPECT_TRUE(c.empty());
  EXPECT_FALSE(c.is_free(0.0, 0.0));
  EXPECT_FALSE(c.segment_is_free({0.0, 0.0}, {0.1, 0.0}));
}

TEST(Costmap, BlocksOccupiedAndUnknownCellsByDefault) {
  OccupancyGrid g;
  fill(g, 0, 0, 39, 39, false);
  set_occupied(g, {20, 20});
  CostmapOptions o;
  o.robot_radius = 0.0;
  const Costmap c(g, o);
  EXPECT_TRUE(c.cell_is_free({10, 10}));
  EXPECT_FALSE(c.cell_is_free({20, 20}));
  EXPECT_FALSE(c.cell_is_free({45, 10})) << "unknown cell inside the raster";
  EXPECT_FALSE(c.cell_is_free({-500, 10})) << "outside the raster";
}

TEST(Costmap, UnknownIsFreeWhenAsked) {
  OccupancyGrid g;
  fill(g, 0, 0, 39, 39, false);
  CostmapOptions o;
  o.robot_radius = 0.0;
  o.unknown_is_free = true;
  const Costmap c(g, o);
  EXPECT_TRUE(c.cell_is_free({45, 10}));
  EXPECT_FALSE(c.cell_is_free({-500, 10})) << "outside the raster stays blocked";
}

TEST(Costmap, OccupiedThresholdDecides) {
  OccupancyGrid g;
  fill(g, 0, 0, 9, 9, false);
  g.add_log_odds({5, 5}, g.fixed_hit() - g.fixed_miss());  // from p = 0.40 to p = 0.70
  ASSERT_NEAR(g.probability({5, 5}), 0.70, 0.01);
  CostmapOptions o;
  o.robot_radius = 0.0;
  EXPECT_FALSE(Costmap(g, o).cell_is_free({5, 5}));
  o.occupied_threshold = 0.75;
  EXPECT_TRUE(Costmap(g, o).cell_is_free({5, 5}));
}

TEST(Costmap, InflatesObstaclesByRobotRadius) {
  OccupancyGrid g;
  fill(g, 0, 0, 59, 59, false);
  set_occupied(g, {30, 30});
  CostmapOptions o;  // 0.25 m = 5 cells
  const Costmap c(g, o);
  EXPECT_FALSE(c.cell_is_free({35, 30}));  // centre exactly 0.25 m away: blocked
  EXPECT_TRUE(c.cell_is_free({36, 30}));
  EXPECT_FALSE(c.cell_is_free({33, 34}));  // 5 cells diagonal-ish: 3-4-5
  EXPECT_TRUE(c.cell_is_free({34, 34}));   // sqrt(32) > 5
}

TEST(Costmap, TheBodyFitsWhereOnlyTheSafetyMarginCloses) {
  OccupancyGrid g;
  fill(g, 0, 0, 59, 59, false);
  set_occupied(g, {30, 30});
  CostmapOptions o;  // 0.25 m = 5 cells, of which 0.1 m = 2 cells margin: the body is 3 cells
  o.safety_margin = 0.1;
  const Costmap c(g, o);
  EXPECT_FALSE(c.cell_is_free({34, 30}));
  EXPECT_TRUE(c.cell_fits_body({34, 30}));
  EXPECT_FALSE(c.cell_fits_body({33, 30})) << "centre exactly at the body radius";
  EXPECT_TRUE(c.cell_is_free({36, 30}) && c.cell_fits_body({36, 30}));
  EXPECT_FALSE(c.cell_fits_body({-500, 10})) << "outside the raster";
  // A path 4 cells past the obstacle keeps the body clear but not the margin.
  const Path past{{1.0, 1.725}, {2.0, 1.725}};
  EXPECT_FALSE(c.path_is_free(past));
  EXPECT_TRUE(c.path_fits_body(past));
  EXPECT_FALSE(c.path_fits_body({{1.0, 1.525}, {2.0, 1.525}}));
  EXPECT_EQ(c.free_cell_count(), Costmap(g, CostmapOptions{}).free_cell_count()) << "the margin still plans";
}

TEST(Costmap, RejectsAMarginWiderThanTheRadius) {
  CostmapOptions o;
  o.safety_margin = 0.3;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o.safety_margin = -0.01;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

TEST(Costmap, InflationMatchesBruteForceOnRandomGrids) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    OccupancyGrid g;
    fill(g, 0, 0, 69, 49, false);
    std::uniform_int_distribution<int> x(0, 69), y(0, 49);
    for (int i = 0; i < 40; ++i) set_occupied(g, {x(rng), y(rng)});
    CostmapOptions o;
    o.robot_radius = 0.03 + 0.05 * trial;
    const Costmap c(g, o);
    const testing::Oracle oracle = testing::brute_force_costmap(g, c, o);
    for (int cy = c.origin().y; cy < c.origin().y + c.height(); ++cy) {
      for (int cx = c.origin().x; cx < c.origin().x + c.width(); ++cx) {
        ASSERT_EQ(c.cell_is_free({cx, cy}), !oracle.cell_blocked(cx, cy))
            << "cell " << cx << "," << cy << " radius " << o.robot_radius;
      }
    }
  }
}

// Property: updating the window where cells changed gives the raster of a rebuild, for
// random changes (walls appear and clear, unknown cells become known) and radii.
TEST(Costmap, UpdateOfAWindowEqualsARebuild) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    OccupancyGrid g;
    fill(g, 0, 0, 79, 59, false);  // known bounds: whole tiles, so changes inside keep them
    std::uniform_int_distribution<int> x(0, 79), y(0, 59), side(0, 12);
    for (int i = 0; i < 40; ++i) set_occupied(g, {x(rng), y(rng)});
    CostmapOptions o;
    o.robot_radius = 0.02 + 0.04 * (trial % 6);
    o.unknown_is_free = trial % 2 == 1;
    Costmap c(g, o);
    const CellIndex lo{x(rng) - 6, y(rng) - 6};
    const CellIndex hi{lo.x + side(rng), lo.y + side(rng)};
    std::uniform_int_distribution<int> wx(lo.x, hi.x), wy(lo.y, hi.y);
    for (int i = 0; i < 15; ++i) {
      const CellIndex w{wx(rng), wy(rng)};
      if (i % 3 == 0)
        fill(g, w.x, w.y, w.x, w.y, false);  // a wall cell cleared
      else
        set_occupied(g, w);
    }
    c.update(g, lo, hi);
    const Costmap rebuilt(g, o);
    ASSERT_EQ(c.origin(), rebuilt.origin());
    ASSERT_EQ(c.width(), rebuilt.width());
    for (int cy = c.origin().y - 1; cy <= c.origin().y + c.height(); ++cy)
      for (int cx = c.origin().x - 1; cx <= c.origin().x + c.width(); ++cx)
        ASSERT_EQ(c.cell_is_free({cx, cy}), rebuilt.cell_is_free({cx, cy}))
            << "trial " << trial << " cell " << cx << "," << cy << " window " << lo.x << "," << lo.y << " .. " << hi.x
            << "," << hi.y;
  }
  // Cells outside the known bounds: the raster grows with a rebuild.
  OccupancyGrid g;
  fill(g, 0, 0, 39, 39, false);
  Costmap c(g, {});
  fill(g, 100, 0, 110, 10, false);
  c.update(g, {100, 0}, {110, 10});
  EXPECT_TRUE(c.cell_is_free({105, 5}));
  EXPECT_EQ(c.width(), Costmap(g, {}).width());
}

TEST(Costmap, SegmentCannotSlipBetweenDiagonalObstacles) {
  OccupancyGrid g;
  fill(g, 0, 0, 19, 19, false);
  set_occupied(g, {10, 10});
  set_occupied(g, {11, 11});
  CostmapOptions o;
  o.robot_radius = 0.0;
  const Costmap c(g, o);
  // Through the shared corner (0.55, 0.55) of the two obstacles, from (10,11) to (11,10).
  EXPECT_FALSE(c.segment_is_free({0.525, 0.575}, {0.575, 0.525}));
  EXPECT_TRUE(c.segment_is_free({0.1, 0.1}, {0.1, 0.9}));
  EXPECT_FALSE(c.segment_is_free({0.1, 0.525}, {0.9, 0.525}));  // through cell (10,10)
}

TEST(Costmap, SegmentCheckMatchesOracleOnRandomSegments) {
  std::mt19937 rng(11);
  OccupancyGrid g;
  fill(g, 0, 0, 59, 59, false);
  std::uniform_int_distribution<int> cell(0, 59);
  for (int i = 0; i < 60; ++i) set_occupied(g, {cell(rng), cell(rng)});
  CostmapOptions o;
  o.robot_radius = 0.05;
  const Costmap c(g, o);
  const testing::Oracle oracle = testing::brute_force_costmap(g, c, o);
  std::uniform_real_distribution<double> pos(-0.2, 3.2);
  int disagreements = 0;
  for (int i = 0; i < 3000; ++i) {
    const Point2 a{pos(rng), pos(rng)};
    const Point2 b{pos(rng), pos(rng)};
    if (c.segment_is_free(a, b) != oracle.segment_free(a, b)) ++disagreements;
  }
  EXPECT_EQ(disagreements, 0);
}

TEST(Costmap, RejectsInvalidOptions) {
  const OccupancyGrid g;
  CostmapOptions o;
  o.robot_radius = -0.1;
  EXPECT_THROW(Costmap(g, o), std::invalid_argument);
  o = {};
  o.occupied_threshold = 0.5;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.margin = std::nan("");
  try {
    validate(o);
    FAIL() << "NaN margin accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("CostmapOptions.margin"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lookahead::planner
