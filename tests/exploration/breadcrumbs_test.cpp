// SPDX-License-Identifier: MIT
// The way back out of a place whose door the safety margin closed behind the robot: the
// trail as a stack, and the escape plan on a hand-made grid of two rooms joined by a 0.3 m door.
#include "lookahead/exploration/breadcrumbs.hpp"

#include <gtest/gtest.h>

#include "hand_made_grid.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"
#include "lookahead/exploration/target_selection.hpp"
#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {
namespace {

using slam::OccupancyGrid;

TEST(Breadcrumbs, CrumbsAreDroppedAtTheirSpacing) {
  Breadcrumbs c(0.125);
  for (int i = 0; i <= 64; ++i) c.drop({i / 64.0, 0.0});  // 1 m in steps of 1/64 m (exact)
  EXPECT_EQ(c.size(), 9U);                                // 0, 0.125, ..., 1
  EXPECT_THROW(Breadcrumbs(0.0), std::invalid_argument);
}

TEST(Breadcrumbs, BacktrackRetracesNewestFirstAndPopsWhatItRetraced) {
  Breadcrumbs c(0.1);
  for (int i = 0; i <= 10; ++i) c.drop({1.0 * i, 0.0});  // x = 0 .. 10
  const auto outside = [](planner::Point2 p) { return p.x < 4.5; };
  const planner::Path back = c.backtrack({10.2, 0.0}, outside);
  ASSERT_EQ(back.size(), 8U);  // from, then crumbs 10, 9, ..., 4
  EXPECT_DOUBLE_EQ(back.front().x, 10.2);
  EXPECT_DOUBLE_EQ(back[1].x, 10.0);
  EXPECT_DOUBLE_EQ(back.back().x, 4.0);
  EXPECT_EQ(c.size(), 5U);  // crumbs 0 .. 4: the exit crumb stays

  // From the exit crumb, the next backtrack never leads back to the place it left.
  const planner::Path further = c.backtrack({4.0, 0.0}, [](planner::Point2 p) { return p.x < 2.5; });
  ASSERT_EQ(further.size(), 4U);  // from, 4, 3, 2
  EXPECT_DOUBLE_EQ(further.back().x, 2.0);

  EXPECT_TRUE(c.backtrack({2.0, 0.0}, [](planner::Point2) { return false; }).empty());
  EXPECT_EQ(c.size(), 3U);  // nothing popped when no crumb qualifies
}

// A trail that comes back past its own start (a robot standing in a door it drove through
// long ago): retracing all of it would take the robot away from the door and the next
// selection back into it, again and again; where its passes meet it takes the short way.
TEST(Breadcrumbs, BacktrackTakesTheShortestWayAlongTheTrailWhereItsPassesMeet) {
  Breadcrumbs c(0.1);
  const auto leg = [&](planner::Point2 a, planner::Point2 b) {
    for (int i = 0; i <= 50; ++i) c.drop({a.x + (b.x - a.x) * i / 50.0, a.y + (b.y - a.y) * i / 50.0});
  };
  leg({0.0, 0.0}, {5.0, 0.0});  // out along y = 0 ...
  leg({5.0, 0.0}, {5.0, 3.0});
  leg({5.0, 3.0}, {0.25, 3.0});
  leg({0.25, 3.0}, {0.25, 0.2});  // ... and back down beside the start
  const auto outside = [](planner::Point2 p) { return p.x < 0.01 && p.y < 0.01; };  // the first crumb
  const auto length = [](const planner::Path& p) {
    double l = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) l += planner::distance(p[i - 1], p[i]);
    return l;
  };

  Breadcrumbs open = c;
  const planner::Path shortcut =
      open.backtrack({0.25, 0.2}, outside, [](planner::Point2, planner::Point2) { return true; });
  ASSERT_GE(shortcut.size(), 2U);
  EXPECT_DOUBLE_EQ(shortcut.back().x, 0.0);
  EXPECT_DOUBLE_EQ(shortcut.back().y, 0.0);
  EXPECT_LT(length(shortcut), 0.5);  // across to the first pass, then back along it
  EXPECT_EQ(open.size(), 1U);        // the newer crumbs are popped all the same

  // A wall between the passes (the map's occupied cells say so): the way is the trail.
  Breadcrumbs walled = c;
  const auto wall = [](planner::Point2 a, planner::Point2 b) { return (a.y < 0.1) == (b.y < 0.1); };  // at y = 0.1
  const planner::Path around = walled.backtrack({0.25, 0.2}, outside, wall);
  EXPECT_GT(length(around), 15.0);  // 5 + 3 + 4.75 + 2.8 m back along the loop
  // Without a passability test no passes are joined either.
  EXPECT_GT(length(Breadcrumbs(c).backtrack({0.25, 0.2}, outside)), 15.0);
}

// Two 2 m x 1.5 m rooms (5 cm cells) side by side; the wall between them has a 6-cell
// (0.3 m) door, which a 0.18 m inflation closes. The left room is mapped all round, the right
// one is open on its far side: its frontier is unreachable from the left room.
OccupancyGrid two_rooms() {
  OccupancyGrid g = testing::open_room(82, 30, 82);
  testing::add_rect(g, 40, 0, 41, 13, 6 * g.fixed_hit());   // the wall below the door...
  testing::add_rect(g, 40, 20, 41, 29, 6 * g.fixed_hit());  // ...and above it (door: y cells 14-19)
  return g;
}

TEST(SelectEscape, TheTrailLeadsOutThroughTheDoorTheMarginClosed) {
  const OccupancyGrid map = two_rooms();
  planner::CostmapOptions co;
  co.robot_radius = 0.18;
  co.unknown_is_free = true;
  const planner::Costmap costmap(map, co);
  FrontierDetector frontiers;
  frontiers.rebuild(map);
  const std::unique_ptr<TargetStrategy> strategy = make_strategy("nearest");
  GoalBlacklist blacklist{BlacklistOptions{0.5, 60.0, 2}};
  SelectionInputs in = testing::selection_inputs(map, costmap, frontiers, *strategy, blacklist, {0.5, 0.75, 0.0});
  ASSERT_EQ(select_target(in).outcome, SelectionOutcome::kUnreachable);

  // The robot came from the right room through the door's middle (y = 0.85 m).
  Breadcrumbs crumbs(0.1);
  for (double x = 3.0; x > 0.5; x -= 0.05) crumbs.drop({x, 0.85});
  const Selection s = select_escape(in, crumbs);
  ASSERT_EQ(s.outcome, SelectionOutcome::kPlanned);
  EXPECT_GT(s.goal_x, 2.05 + 0.18);  // beyond the door's inflated band, in the right room
  EXPECT_LT(s.goal_x, 2.6);          // the nearest crumb out, not the far end of the trail
  EXPECT_TRUE(costmap.is_free({s.goal_x, s.goal_y}));
  EXPECT_FALSE(costmap.segment_is_free({0.5, 0.85}, {s.goal_x, s.goal_y}));  // the margin closed it

  // From the goal, the frontier of the right room is within reach again.
  in.pose = {s.goal_x, s.goal_y, 0.0};
  EXPECT_EQ(select_target(in).outcome, SelectionOutcome::kPlanned);

  // With no crumb outside the left room there is no way out: trapped, as before.
  Breadcrumbs inside(0.1);
  for (double x = 1.5; x > 0.5; x -= 0.05) inside.drop({x, 0.85});
  in.pose = {0.5, 0.75, 0.0};
  EXPECT_EQ(select_escape(in, inside).outcome, SelectionOutcome::kUnreachable);
}

// The squeeze rule (Mission::squeeze, the last resort): the 0.3 m door the 0.18 m inflation closes is open to
// a 0.1 m body, so a plan on the map inflated by the body alone reaches the right room.
TEST(Squeeze, TheDoorTheMarginClosedIsOpenToTheBody) {
  const OccupancyGrid map = two_rooms();
  FrontierDetector frontiers;
  frontiers.rebuild(map);
  const std::unique_ptr<TargetStrategy> strategy = make_strategy("nearest");
  GoalBlacklist blacklist{BlacklistOptions{0.5, 60.0, 2}};
  planner::CostmapOptions co;
  co.unknown_is_free = true;
  co.robot_radius = 0.18;  // body 0.1 m + margin 0.08 m
  const planner::Costmap with_margin(map, co);
  co.robot_radius = 0.1;
  const planner::Costmap body(map, co);
  SelectionInputs in = testing::selection_inputs(map, with_margin, frontiers, *strategy, blacklist, {0.5, 0.75, 0.0});
  EXPECT_EQ(select_target(in).outcome, SelectionOutcome::kUnreachable);
  in.costmap = &body;
  const Selection s = select_target(in);
  ASSERT_EQ(s.outcome, SelectionOutcome::kPlanned);
  EXPECT_GT(s.goal_x, 2.05);  // in the right room, through the door
  EXPECT_TRUE(body.path_is_free(s.path));
  EXPECT_FALSE(with_margin.path_is_free(s.path));
}

}  // namespace
}  // namespace lookahead::exploration
