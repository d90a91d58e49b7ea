// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/frontier_cell.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lookahead::slam {
namespace {

// Log-odds x 1000: free (p 0.27), wall (p 0.95), undecided leaning free (p 0.43: a cell one
// grazing beam crossed) and undecided leaning occupied (p 0.55: a wall cell hit once and
// crossed twice).
constexpr int kFree = -1000, kWall = 3000, kUndecided = -300, kErodedWall = 200;

// A free 5 x 5 block, cells (0..4, 0..4), in never-seen space.
OccupancyGrid free_block() {
  OccupancyGrid g;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) g.add_log_odds({x, y}, kFree);
  return g;
}

FrontierCellRule mission_rule() {
  FrontierCellRule r;
  r.undecided_band = 2;
  r.skip_wall_cells = true;
  return r;
}

TEST(FrontierCell, PlainRuleIsAFreeCellNextToNeverSeenSpace) {
  const OccupancyGrid g = free_block();
  const FrontierCellTest plain;
  EXPECT_TRUE(plain.is_frontier(g, {4, 2}));  // (5, 2) never seen
  EXPECT_TRUE(plain.is_frontier(g, {0, 0}));
  EXPECT_FALSE(plain.is_frontier(g, {2, 2}));  // inside
  EXPECT_FALSE(plain.is_frontier(g, {5, 2}));  // never seen itself
}

TEST(FrontierCell, DiagonalUnknownAloneIsNoFrontier) {
  OccupancyGrid g = free_block();
  for (int x = 5; x < 7; ++x)
    for (int y = 0; y < 5; ++y) g.add_log_odds({x, y}, kFree);
  for (int y = 0; y < 2; ++y) g.add_log_odds({y, 5}, kFree);
  // (4, 4): right (5, 4) free, up (4, 5) never seen; (3, 4): up (3, 5) never seen.
  const FrontierCellTest plain;
  EXPECT_TRUE(plain.is_frontier(g, {4, 4}));
  // (1, 4): up (1, 5) free, left and right free, down free; only diagonal (2, 5) unknown.
  EXPECT_FALSE(plain.is_frontier(g, {1, 4}));
}

TEST(FrontierCell, WallCellsAreSkippedOnlyWhenAsked) {
  OccupancyGrid g = free_block();
  g.add_log_odds({5, 2}, kWall);
  const FrontierCellTest plain, mission(mission_rule());
  // (4, 1): (5, 1) never seen, (5, 2) a wall on the diagonal.
  EXPECT_TRUE(plain.is_frontier(g, {4, 1}));
  EXPECT_FALSE(mission.is_frontier(g, {4, 1}));
  EXPECT_TRUE(mission.is_occupied(g, {5, 2}));
  EXPECT_FALSE(mission.is_free(g, {5, 2}));
}

TEST(FrontierCell, UndecidedBandCountsOnlyNearNeverSeenSpace) {
  OccupancyGrid g = free_block();
  for (int y = 0; y < 5; ++y) g.add_log_odds({5, y}, kUndecided);  // a band one cell wide
  const FrontierCellTest plain, mission(mission_rule());
  EXPECT_FALSE(plain.is_frontier(g, {4, 2}));   // undecided is not never seen
  EXPECT_TRUE(mission.is_frontier(g, {4, 2}));  // (6, 2) never seen, within the band
  // Seal the band with 3 free columns: its cells are then deep in the known map.
  for (int x = 6; x < 9; ++x)
    for (int y = -3; y < 8; ++y) g.add_log_odds({x, y}, kFree);
  for (int x = -3; x < 6; ++x)
    for (int y = 5; y < 8; ++y) g.add_log_odds({x, y}, kFree);
  for (int x = -3; x < 6; ++x)
    for (int y = -3; y < 0; ++y) g.add_log_odds({x, y}, kFree);
  EXPECT_FALSE(mission.is_frontier(g, {4, 2}));
}

TEST(FrontierCell, AnErodedWallIsNoWayOut) {
  // Column 5 is a wall that beams grazed: its cells lean occupied but are undecided, with
  // never-seen space behind it. Under the plain rule undecided cells never count; under the
  // mission's rule they do only when they lean free.
  OccupancyGrid g = free_block();
  for (int y = 0; y < 5; ++y) g.add_log_odds({5, y}, kErodedWall);
  const FrontierCellTest mission(mission_rule());
  for (int y = 0; y < 5; ++y) EXPECT_FALSE(mission.is_frontier(g, {4, y})) << y;
  // A gap in it: (5, 2) crossed often enough to be free. Its neighbours (5, 1) and (5, 3)
  // still lean occupied, so the gap is the unseen inside of the wall, not a door.
  g.add_log_odds({5, 2}, -1500);
  ASSERT_TRUE(mission.is_free(g, {5, 2}));
  EXPECT_FALSE(mission.is_frontier(g, {5, 2}));
  // The same column leaning free (one grazing beam each) hides a way out: frontier.
  OccupancyGrid crossed = free_block();
  for (int y = 0; y < 5; ++y) crossed.add_log_odds({5, y}, kUndecided);
  EXPECT_TRUE(mission.is_frontier(crossed, {4, 2}));
}

TEST(FrontierCell, ThresholdsOutOfRangeAreRejected) {
  FrontierCellRule r;
  r.free_threshold = 0.5;
  EXPECT_THROW(FrontierCellTest{r}, std::invalid_argument);
  r = {};
  r.occupied_threshold = 1.0;
  EXPECT_THROW(FrontierCellTest{r}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam
