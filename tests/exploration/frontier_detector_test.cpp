// SPDX-License-Identifier: MIT
#include "lookahead/exploration/frontier_detector.hpp"

#include <gtest/gtest.h>

#include "hand_made_grid.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"

namespace lookahead::exploration {
namespace {

using slam::CellIndex;
using slam::OccupancyGrid;

void set_free(OccupancyGrid& g, int x0, int y0, int x1, int y1) {
  testing::add_rect(g, x0, y0, x1, y1, 3 * g.fixed_miss());
}
void set_wall(OccupancyGrid& g, int x0, int y0, int x1, int y1) {
  testing::add_rect(g, x0, y0, x1, y1, 3 * g.fixed_hit());
}

// A 40 x 20 cell room with walls, open on its right side: the frontier is that side.
OccupancyGrid open_room() { return testing::open_room(40, 20, 40); }

// The detector compares raw log-odds against precomputed thresholds instead of calling
// probability(): every log-odds value must get the same answer either way.
TEST(FrontierDetector, FreeCellsAreThoseBelowTheFreeProbability) {
  for (const double threshold : {0.35, 0.2, 0.45}) {
    FrontierOptions o;
    o.free_threshold = threshold;
    const FrontierDetector d(o);
    slam::OccupancyGrid g;
    for (int l = -4000; l <= 4000; ++l) {
      const slam::CellIndex c{l + 4000, 0};
      g.add_log_odds(c, l);
      if (g.raw_log_odds(c) != l) continue;  // clamped
      ASSERT_EQ(d.is_free(g, c), g.probability(c) < threshold) << "log-odds " << l << ", threshold " << threshold;
    }
  }
}

TEST(FrontierDetector, FreeCellsNextToUnknownAreFrontiers) {
  const OccupancyGrid g = open_room();
  FrontierDetector d;
  d.rebuild(g);
  // The column x = 39, y = 1..18: the two end cells touch the walls, and a free cell that
  // touches a wall and unknown space is the wall's unseen inside, not a frontier.
  EXPECT_EQ(d.cells().size(), 18u);
  for (const CellIndex c : d.cells()) EXPECT_EQ(c.x, 39);
  EXPECT_FALSE(d.is_frontier(g, {20, 10}));  // inside
  EXPECT_FALSE(d.is_frontier(g, {-1, 5}));   // wall
}

// The edge of the seen region is often a band
// of cells one grazing beam crossed, known but neither free nor occupied. The frontier is
// the free side of that band, not hidden behind it.
TEST(FrontierDetector, CellsOneBeamCrossedDoNotHideTheFrontier) {
  OccupancyGrid g = open_room();
  for (int y = 0; y <= 19; ++y) g.add_log_odds({40, y}, g.fixed_miss());  // one miss: undecided
  ASSERT_TRUE(g.is_known({40, 5}));
  ASSERT_GT(g.probability({40, 5}), FrontierOptions{}.free_threshold);
  FrontierDetector d;
  d.rebuild(g);
  EXPECT_EQ(d.cells().size(), 18u);  // x = 39 again, y = 1..18
  for (const CellIndex c : d.cells()) EXPECT_EQ(c.x, 39);
}

// ...but an undecided cell deep inside the known map (a wall edge blurred by SLAM's pose
// noise, or a single noisy beam) is no way into new space: no frontier around it.
TEST(FrontierDetector, UndecidedCellsInsideTheKnownMapAreNoFrontier) {
  OccupancyGrid g = open_room();
  for (int x = 10; x <= 20; ++x) g.add_log_odds({x, 10}, -3 * g.fixed_miss());  // 11 cells: p = 0.5
  ASSERT_GT(g.probability({15, 10}), FrontierOptions{}.free_threshold);
  ASSERT_LT(g.probability({15, 10}), FrontierOptions{}.occupied_threshold);
  FrontierDetector d;
  d.rebuild(g);
  EXPECT_EQ(d.cells().size(), 18u);  // the open side only
  for (const CellIndex c : d.cells()) EXPECT_EQ(c.x, 39);
}

TEST(FrontierDetector, ClusterGoalIsFreeWithClearance) {
  const OccupancyGrid g = open_room();
  FrontierDetector d;
  d.rebuild(g);
  const auto clusters = d.clusters(g);
  ASSERT_EQ(clusters.size(), 1u);
  ASSERT_TRUE(clusters[0].has_goal);
  EXPECT_NEAR(clusters[0].goal_y, clusters[0].centroid_y, 0.06);
  const CellIndex goal = g.cell_at(clusters[0].goal_x, clusters[0].goal_y);
  EXPECT_TRUE(d.is_free(g, goal));
}

// The centroid of an L-shaped frontier lies in unknown space; the goal must not.
TEST(FrontierDetector, GoalOfAnLShapedFrontierIsNotTheCentroid) {
  OccupancyGrid g;
  set_free(g, 0, 0, 29, 29);
  FrontierDetector d;
  d.rebuild(g);
  auto clusters = d.clusters(g);
  ASSERT_EQ(clusters.size(), 1u);  // the whole border is one ring
  ASSERT_TRUE(clusters[0].has_goal);
  EXPECT_TRUE(d.is_free(g, g.cell_at(clusters[0].goal_x, clusters[0].goal_y)));
}

TEST(FrontierDetector, NarrowGapWithoutClearanceHasNoGoal) {
  OccupancyGrid g;
  set_wall(g, 0, 0, 30, 30);
  set_free(g, 10, 10, 10, 31);  // a one-cell slit through the walls, opening on unknown space
  FrontierOptions o;
  o.min_cluster_cells = 1;
  FrontierDetector d(o);
  d.rebuild(g);
  // The slit's cells touch walls, so they are no frontier, and nothing gives a goal.
  EXPECT_FALSE(d.is_frontier(g, {10, 31}));
  for (const auto& c : d.clusters(g)) EXPECT_FALSE(c.has_goal);  // a 5 cm slit fits no robot
}

TEST(FrontierDetector, IncrementalUpdateMatchesRebuild) {
  OccupancyGrid g = open_room();
  FrontierDetector incremental;
  incremental.rebuild(g);
  set_free(g, 40, 0, 55, 19);  // the robot saw further right, corridor walls included
  set_wall(g, 40, -1, 56, -1);
  set_wall(g, 40, 20, 56, 20);
  incremental.update(g, {40, -1}, {56, 20});
  FrontierDetector full;
  full.rebuild(g);
  EXPECT_EQ(incremental.cells(), full.cells());
  for (const CellIndex c : full.cells()) EXPECT_EQ(c.x, 55);
}

TEST(FrontierDetector, SmallClustersAreIgnored) {
  OccupancyGrid g = open_room();
  set_wall(g, 39, 0, 39, 16);  // only three frontier cells stay open
  FrontierDetector d;
  d.rebuild(g);
  EXPECT_TRUE(d.clusters(g).empty());
}

// The frontier is x = 39, y = 1..18 (0.05 m cells). Standing at its middle and still
// seeing it means the space behind cannot be seen: the cells near the robot retire for good,
// the rest stay, and updates do not bring the retired ones back.
TEST(FrontierDetector, RetiredCellsStayRetired) {
  OccupancyGrid g = open_room();
  FrontierDetector d;
  d.rebuild(g);
  double x, y;
  g.cell_center({39, 10}, x, y);
  EXPECT_EQ(d.retire_near(g, x, y, 0.22), 9u);  // y = 6..14
  EXPECT_EQ(d.retired_count(), 9u);
  EXPECT_EQ(d.cells().size(), 9u);
  EXPECT_FALSE(d.cells().count({39, 10}));
  d.update(g, {0, 0}, {39, 19});
  EXPECT_EQ(d.cells().size(), 9u);
  d.rebuild(g);
  EXPECT_EQ(d.cells().size(), 9u);
  EXPECT_TRUE(d.cells().count({39, 2}));
  // The two short pieces left (4 and 5 cells) are below min_cluster_cells: nothing to go to.
  EXPECT_TRUE(d.clusters(g).empty());
}

TEST(GoalBlacklist, EntriesExpire) {
  GoalBlacklist b({0.5, 10.0});
  b.add(1.0, 1.0, 0.0);
  EXPECT_TRUE(b.contains(1.3, 1.0, 5.0));
  EXPECT_FALSE(b.contains(2.0, 1.0, 5.0));
  EXPECT_FALSE(b.contains(1.0, 1.0, 10.5));
  EXPECT_EQ(b.expire(10.5), 0u);
}

// Regression (the trapped ends): a spot that keeps failing is blacklisted for good after
// max_strikes entries, so a mission waiting for entries to expire cannot wait forever.
TEST(GoalBlacklist, TheThirdStrikeLastsForGood) {
  GoalBlacklist b({0.5, 10.0, 3});
  EXPECT_FALSE(b.add(1.0, 1.0, 0.0));
  EXPECT_FALSE(b.permanent(1.0, 1.0));
  EXPECT_FALSE(b.add(1.2, 1.0, 20.0));  // the same spot (within the radius), second time
  EXPECT_FALSE(b.contains(1.0, 1.0, 31.0));
  EXPECT_TRUE(b.add(0.9, 1.1, 40.0));  // third time: for good
  EXPECT_TRUE(b.permanent(1.0, 1.0));
  EXPECT_TRUE(b.contains(1.0, 1.0, 1e6));
  EXPECT_EQ(b.expire(1e6), 1u);
  EXPECT_FALSE(b.permanent(3.0, 1.0));  // other spots keep their own count
  EXPECT_FALSE(b.add(3.0, 1.0, 40.0));
}

// The second chance before "trapped": spots blacklisted for good get all their strikes back;
// entries that only wait to expire stay.
TEST(GoalBlacklist, ForgivingGivesPermanentSpotsTheirStrikesBack) {
  GoalBlacklist b({0.5, 10.0, 2});
  b.add(1.0, 1.0, 0.0);
  EXPECT_TRUE(b.add(1.0, 1.0, 20.0));  // for good
  b.add(3.0, 1.0, 25.0);               // one strike, expires at 35
  EXPECT_EQ(b.forgive_permanent(), 1u);
  EXPECT_FALSE(b.permanent(1.0, 1.0));
  EXPECT_FALSE(b.contains(1.0, 1.0, 30.0));
  EXPECT_TRUE(b.contains(3.0, 1.0, 30.0));
  EXPECT_FALSE(b.add(1.0, 1.0, 40.0));  // the count starts again
  EXPECT_TRUE(b.add(3.0, 1.0, 40.0));   // the other spot kept its strike
  EXPECT_EQ(b.forgive_permanent(), 1u);
  EXPECT_EQ(b.forgive_permanent(), 0u);
}

}  // namespace
}  // namespace lookahead::exploration
