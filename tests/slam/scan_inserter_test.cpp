// SPDX-License-Identifier: MIT
#include "lookahead/slam/sensor/scan_inserter.hpp"

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
    trace_cells(a, b, [&](CellIndex x) {
      cells.push_back(x);
      return true;
    });
    ASSERT_EQ(cells.front(), a);
    ASSERT_EQ(cells.back(), b);
    ASSERT_EQ(cells.size(), static_cast<std::size_t>(std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)) + 1));
    for (std::size_t i = 1; i < cells.size(); ++i) {
      ASSERT_LE(std::abs(cells[i].x - cells[i - 1].x), 1);
      ASSERT_LE(std::abs(cells[i].y - cells[i - 1].y), 1);
    }
  }
}

// Does the segment a-b pass through the closed unit cell c? (Liang-Barsky clip.)
bool crosses(double ax, double ay, double bx, double by, CellIndex c) {
  double t0 = 0.0, t1 = 1.0;
  const auto clip = [&](double p, double q) {
    if (p == 0.0) return q >= -1e-9;
    const double r = q / p;
    if (p < 0)
      t0 = std::max(t0, r);
    else
      t1 = std::min(t1, r);
    return t0 <= t1 + 1e-9;
  };
  return clip(-(bx - ax), ax - c.x) && clip(bx - ax, c.x + 1 - ax) && clip(-(by - ay), ay - c.y) &&
         clip(by - ay, c.y + 1 - ay);
}

// Property: every cell trace_segment visits is one the true segment passes through; the
// trace starts in the start's cell, ends in the end's and never repeats. (It may skip a
// cell next to either end: a beam's misses need not touch every cell it grazes.)
TEST(ScanInserter, TraceSegmentVisitsOnlyCellsTheSegmentCrosses) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-60.0, 60.0);
  for (int k = 0; k < 2000; ++k) {
    const double ax = u(rng), ay = u(rng);
    const double bx = k % 4 == 0 ? ax + u(rng) / 100 : u(rng), by = u(rng);  // some short ones
    std::vector<CellIndex> cells;
    trace_segment(ax, ay, bx, by, [&](CellIndex c) {
      cells.push_back(c);
      return true;
    });
    const CellIndex a{static_cast<int>(std::floor(ax)), static_cast<int>(std::floor(ay))};
    const CellIndex b{static_cast<int>(std::floor(bx)), static_cast<int>(std::floor(by))};
    ASSERT_EQ(cells.front(), a) << k;
    ASSERT_EQ(cells.back(), b) << k;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      ASSERT_TRUE(crosses(ax, ay, bx, by, cells[i])) << k << " cell " << i;
      if (i == 0) continue;
      ASSERT_FALSE(cells[i] == cells[i - 1]) << k;
    }
  }
}

// Regression (KTH corridors): a beam grazing a wall and ending on its face. The wall fills
// the rows below y = 10; the beam comes in at a slope of 1/40 and ends 0.001 cell inside it.
// Cell centre to cell centre, the line is in the wall's row for its last 20 cells; the
// true segment is not before its end cell.
TEST(ScanInserter, AGrazingBeamDoesNotEraseTheWallItEndsOn) {
  const double ax = 0.5, ay = 10.999, bx = 40.5, by = 9.999;
  int wall_cells_exact = 0, wall_cells_centres = 0;
  trace_segment(ax, ay, bx, by, [&](CellIndex c) {
    wall_cells_exact += c.y < 10;
    return true;
  });
  trace_cells({0, 10}, {40, 9}, [&](CellIndex c) {
    wall_cells_centres += c.y < 10;
    return true;
  });
  EXPECT_EQ(wall_cells_exact, 1);  // the end cell only
  EXPECT_GE(wall_cells_centres, 15);

  // A corridor wall: its face at y = 0.5 m (0.05 m cells: the wall's top row is y cell 9).
  // The robot drives along at y = 1.2 m; each pose sees the wall beside it with a steep
  // beam and 2-12 m ahead with grazing ones, every 5 cm.
  OccupancyGrid exact, centres;
  InsertOptions on;
  on.exact_rays = true;
  const auto beam_to = [&](double x, double y, double ex, double ey) {
    const Pose2 pose{x, y, std::atan2(ey - y, ex - x)};
    const LaserScan one = single_beam(static_cast<float>(std::hypot(ex - x, ey - y)));
    insert_scan(exact, pose, one, on);
    insert_scan(centres, pose, one, {});
  };
  for (double x = 0.0; x <= 5.0; x += 0.25) {
    beam_to(x, 1.2, x, 0.4999);
    for (double d = 2.0; d <= 12.0; d += 0.05) beam_to(x, 1.2, x + d, 0.4999);
  }
  int kept_exact = 0, kept_centres = 0;
  for (int cx = 40; cx <= 140; ++cx) {
    kept_exact += exact.probability({cx, 9}) > 0.5;
    kept_centres += centres.probability({cx, 9}) > 0.5;
  }
  // Of the 101 wall cells 2-7 m along (each the end of some grazing beam): exact rays keep
  // them (101 here), centre-to-centre rays erase a quarter (75 kept here).
  EXPECT_GE(kept_exact, 95);
  EXPECT_LE(kept_centres, 85);
}

}  // namespace
}  // namespace lookahead::slam
