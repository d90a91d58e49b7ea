// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/scan_inserter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace lookahead::slam {
namespace {

LaserScan single_beam(float range) {
  LaserScan s;
  s.ranges = {range};
  s.angle_min = 0.0;
  s.angle_increment = 0.0;
  s.max_range = 80.0;
  return s;
}

TEST(ScanInserter, BeamClearsItsPathAndMarksItsEnd) {
  OccupancyGrid g;
  insert_scan(g, {0.025, 0.025, 0.0}, single_beam(1.0f), {});
  for (int x = 0; x < 20; ++x) EXPECT_LT(g.probability({x, 0}), 0.5) << x;
  EXPECT_TRUE(g.is_obstacle({20, 0}));
  EXPECT_FALSE(g.is_known({21, 0}));
  EXPECT_FALSE(g.is_known({10, 1}));
}

TEST(ScanInserter, RayStopsAtMaxUsableRange) {
  OccupancyGrid g;
  InsertOptions o;
  o.max_usable_range = 0.5;
  insert_scan(g, {0.025, 0.025, 0.0}, single_beam(2.0f), o);
  EXPECT_LT(g.probability({10, 0}), 0.5);  // cropped end is free, not an obstacle
  EXPECT_FALSE(g.is_obstacle({10, 0}));
  EXPECT_FALSE(g.is_known({11, 0}));
  EXPECT_FALSE(g.is_known({40, 0}));
}

TEST(ScanInserter, NoReturnsLeaveTheMapUntouched) {
  OccupancyGrid g;
  insert_scan(g, {}, single_beam(std::numeric_limits<float>::quiet_NaN()), {});
  insert_scan(g, {}, single_beam(std::numeric_limits<float>::infinity()), {});
  insert_scan(g, {}, single_beam(81.9f), {});
  CellIndex lo, hi;
  EXPECT_FALSE(g.known_bounds(lo, hi));
}

TEST(ScanInserter, NoReturnsClearUpToMaxRangeWhenAsked) {
  OccupancyGrid g;
  LaserScan s = single_beam(std::numeric_limits<float>::infinity());
  s.max_range = 1.0;
  InsertOptions o;
  o.clear_no_returns = true;
  insert_scan(g, {0.025, 0.025, 0.0}, s, o);
  EXPECT_LT(g.probability({19, 0}), 0.5);
  EXPECT_LT(g.probability({20, 0}), 0.5);  // free to the max range, no obstacle at its end
  EXPECT_FALSE(g.is_obstacle({20, 0}));
  EXPECT_FALSE(g.is_known({21, 0}));
}

TEST(ScanInserter, LaserOffsetMovesTheOrigin) {
  OccupancyGrid g;
  LaserScan s = single_beam(1.0f);
  s.laser_offset = {0.5, 0.0, M_PI / 2};  // mounted ahead, looking left
  insert_scan(g, {0.025, 0.025, 0.0}, s, {});
  EXPECT_TRUE(g.is_obstacle(g.cell_at(0.525, 1.025)));
}

// Property: traced cells are 8-connected, start and end where asked, and never repeat.
TEST(ScanInserter, TraceCellsIsConnectedAndEndsAtTarget) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> c(-200, 200);
  for (int k = 0; k < 500; ++k) {
    const CellIndex a{c(rng), c(rng)}, b{c(rng), c(rng)};
    std::vector<CellIndex> cells;
    trace_cells(a, b, [&](CellIndex x) { cells.push_back(x); return true; });
    ASSERT_EQ(cells.front(), a);
    ASSERT_EQ(cells.back(), b);
    ASSERT_EQ(cells.size(), static_cast<std::size_t>(std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)) + 1));
    for (std::size_t i = 1; i < cells.size(); ++i) {
      ASSERT_LE(std::abs(cells[i].x - cells[i - 1].x), 1);
      ASSERT_LE(std::abs(cells[i].y - cells[i - 1].y), 1);
    }
  }
}

}  // namespace
}  // namespace lookahead::slam
