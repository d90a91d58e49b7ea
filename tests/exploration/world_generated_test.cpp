// SPDX-License-Identifier: MIT
// Generated office, P-SLAM maze and corridor: documented dimensions, and every free cell reachable.
#include <gtest/gtest.h>

#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/robot.hpp"
#include "lookahead/exploration/world_reachability.hpp"

namespace lookahead::exploration {
namespace {

TEST(GeneratedWorlds, OfficeHasTheDocumentedSize) {
  const OfficeOptions o;
  const GeneratedWorld g = make_office(o);
  EXPECT_NEAR(o.width_m(), 39.75, 1e-9);
  EXPECT_NEAR(o.height_m(), 19.8, 1e-9);
  EXPECT_NEAR(g.world.width_m(), 39.75, g.world.resolution());
  EXPECT_NEAR(g.world.height_m(), 19.8, g.world.resolution());
  // Free space: 16 rooms, the corridor and 16 door gaps through 0.15 m walls.
  const double expected = 16 * 4.8 * 8.4 + (39.75 - 0.3) * 2.4 + 16 * 1.0 * 0.15;
  EXPECT_NEAR(g.world.free_area_m2(), expected, 0.02 * expected);
  EXPECT_FALSE(disc_collides(g.world, {g.start.x, g.start.y}, 0.5));
}

TEST(GeneratedWorlds, OfficeIsConnectedForAPointAndForThePioneer) {
  const GeneratedWorld g = make_office();
  const Eigen::Vector2d start(g.start.x, g.start.y);
  const ReachableArea point = reachable_free_area(g.world, start, 0.0);
  ASSERT_TRUE(point.start_valid);
  EXPECT_EQ(point.reachable_cells, g.world.free_cell_count());
  // The 0.25 m disc gets through every 1 m door; only the corners it cannot sweep are lost.
  const ReachableArea disc = reachable_free_area(g.world, start, 0.25);
  EXPECT_GT(disc.area_m2, 0.97 * g.world.free_area_m2());
  const OfficeOptions o;
  for (int i = 0; i < o.rooms_per_side; ++i) {
    const double x = o.wall_thickness + i * (o.room_width + o.wall_thickness) + o.room_width / 2;
    for (const double y : {2.0, o.height_m() - 2.0}) {
      const auto c = g.world.cell_of({x, y});
      EXPECT_TRUE(disc.centres[static_cast<std::size_t>(c.y * g.world.width() + c.x)]) << x << " " << y;
    }
  }
}

TEST(GeneratedWorlds, OfficeDoorsFollowTheSeed) {
  OfficeOptions a;
  OfficeOptions b;
  b.seed = 2;
  EXPECT_EQ(make_office(a).world.cells(), make_office(a).world.cells());
  EXPECT_NE(make_office(a).world.cells(), make_office(b).world.cells());
  OfficeOptions bad;
  bad.door_width = 5.0;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(GeneratedWorlds, PslamMazeMatchesThePaper) {
  const MazeOptions o;
  EXPECT_EQ(o.blocks_per_side(), 4);
  const GeneratedWorld g = make_pslam_maze(o);
  EXPECT_NEAR(g.world.width_m(), 25.4, 1e-9);
  EXPECT_EQ(g.world.width(), 508);
  // 625 m^2 minus 16 blocks of 3.5 m x 3.5 m.
  EXPECT_NEAR(g.world.free_area_m2(), 625.0 - 16 * 3.5 * 3.5, 1e-6);
  EXPECT_TRUE(g.world.is_occupied(2.2 + 1.75, 2.2 + 1.75));  // first block's centre
  EXPECT_FALSE(g.world.is_occupied(2.2 + 3.5 + 1.1, 3.95));  // corridor between blocks
  EXPECT_TRUE(g.world.is_occupied(-0.1, 12.0));              // boundary wall
  EXPECT_FALSE(g.world.is_occupied(24.9, 24.9));
  const ReachableArea point = reachable_free_area(g.world, {g.start.x, g.start.y}, 0.0);
  EXPECT_EQ(point.reachable_cells, g.world.free_cell_count());
  const ReachableArea disc = reachable_free_area(g.world, {g.start.x, g.start.y}, 0.25);
  // Only the corners of the square, which a disc cannot sweep, and the half-cell margin of the
  // conservative inflation are lost.
  EXPECT_GT(disc.area_m2, 0.999 * g.world.free_area_m2());
  MazeOptions odd;
  odd.side = 24.0;
  EXPECT_THROW(odd.validate(), std::invalid_argument);
}

TEST(GeneratedWorlds, PslamCorridorIsAnLWithBoxesTheRobotCanPass) {
  const CorridorOptions o;
  const GeneratedWorld g = make_pslam_corridor(o);
  EXPECT_NEAR(g.world.width_m(), 16.0 + 2.4 + 0.4, 1e-9);
  EXPECT_NEAR(g.world.height_m(), 36.0 + 2.4 + 0.4, 1e-9);
  // Free: the two legs minus their overlap, minus 3 + 8 boxes of 1.0 m x 0.7 m.
  const double legs = 18.4 * 2.4 + 2.4 * 36.0;
  EXPECT_NEAR(g.world.free_area_m2(), legs - 11 * 0.7, 0.01 * legs);
  EXPECT_FALSE(g.world.is_occupied(17.2, 37.9));  // C, the far end
  EXPECT_TRUE(g.world.is_occupied(8.0, 10.0));    // inside the L
  // The first box sits on the lower wall of A-B, near 4 m.
  bool box = false;
  for (double x = 3.5; x < 5.0; x += 0.05) box = box || g.world.is_occupied(x, 0.1);
  EXPECT_TRUE(box);
  const ReachableArea disc = reachable_free_area(g.world, {g.start.x, g.start.y}, 0.25);
  EXPECT_TRUE(disc.start_valid);
  const auto c = g.world.cell_of({17.2, 37.9});
  EXPECT_TRUE(disc.centres[static_cast<std::size_t>(c.y * g.world.width() + c.x)]);
  CorridorOptions other = o;
  other.seed = 2;
  EXPECT_NE(make_pslam_corridor(other).world.cells(), g.world.cells());
  CorridorOptions narrow = o;
  narrow.width = 1.2;
  EXPECT_THROW(narrow.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::exploration
