// SPDX-License-Identifier: MIT
// Target selection on a hand-made grid: what the outcome says when the only reachable
// frontier is blacklisted for a while, and for good.
#include "lookahead/exploration/target_selection.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hand_made_grid.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"
#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {
namespace {

using slam::OccupancyGrid;

// Skips every frontier, as the predictive strategy does when all are predicted.
class SkipsAll : public TargetStrategy {
 public:
  [[nodiscard]] std::string name() const override { return "skips-all"; }
  [[nodiscard]] std::optional<std::size_t> choose(const std::vector<Candidate>&) const override { return std::nullopt; }
  [[nodiscard]] std::optional<std::size_t> choose_any(const std::vector<Candidate>& c) const override {
    return NearestFrontierStrategy().choose(c);
  }
};

// A 3 m x 1.5 m room (5 cm cells), walled except on its right side: one frontier there.
OccupancyGrid open_room() { return testing::open_room(60, 30, 60); }

struct Scene {
  OccupancyGrid map = open_room();
  planner::Costmap costmap;
  FrontierDetector frontiers;
  std::unique_ptr<TargetStrategy> strategy = make_strategy("nearest");
  GoalBlacklist blacklist{BlacklistOptions{0.5, 60.0, 2}};

  Scene() {
    planner::CostmapOptions co;
    co.robot_radius = 0.2;
    co.unknown_is_free = true;
    costmap = planner::Costmap(map, co);
    frontiers.rebuild(map);
  }
  Selection select(double now) {
    SelectionInputs in = testing::selection_inputs(map, costmap, frontiers, *strategy, blacklist, {0.5, 0.75, 0.0});
    in.now = now;
    return select_target(in);
  }
};

// Regression (50052750 with SLAM, trapped at 94.8 %): frontiers that are only blacklisted
// for a while counted towards "trapped" as if no way led there.
TEST(TargetSelection, ABlacklistedFrontierIsWaitedForUntilItsLastStrike) {
  Scene s;
  const Selection first = s.select(0.0);
  ASSERT_EQ(first.outcome, SelectionOutcome::kPlanned);
  EXPECT_FALSE(first.waiting_on_blacklist);

  EXPECT_FALSE(s.blacklist.add(first.goal_x, first.goal_y, 0.0));
  const Selection blocked = s.select(1.0);
  EXPECT_EQ(blocked.outcome, SelectionOutcome::kUnreachable);
  EXPECT_TRUE(blocked.waiting_on_blacklist);

  EXPECT_EQ(s.select(61.0).outcome, SelectionOutcome::kPlanned);  // the entry expired

  EXPECT_TRUE(s.blacklist.add(first.goal_x, first.goal_y, 61.0));  // second strike of two
  const Selection given_up = s.select(200.0);
  EXPECT_EQ(given_up.outcome, SelectionOutcome::kUnreachable);
  EXPECT_FALSE(given_up.waiting_on_blacklist);
}

// A frontier whose far side is only predicted is still unexplored: with every frontier
// skipped the selection plans to one of them (and says so), it never reports "no frontier".
TEST(TargetSelection, EveryFrontierPredictedStillPlansToOne) {
  Scene s;
  s.strategy = std::make_unique<SkipsAll>();
  const Selection sel = s.select(0.0);
  EXPECT_EQ(sel.outcome, SelectionOutcome::kPlanned);
  EXPECT_TRUE(sel.rest_predicted);
  EXPECT_GT(sel.goal_x, 2.5);  // the frontier on the room's open right side
}

// A 0.3 m passage between two rooms, which a 0.2 m body with no margin closes on the
// costmap. The free cell nearest a robot inside it lies in the room beyond the wall above;
// the start of a plan must be one the robot can drive to, along the passage.
TEST(TargetSelection, TheNearestFreeCellIsNotBehindAWall) {
  slam::OccupancyGrid map;
  testing::add_rect(map, 0, 0, 99, 59, 3 * map.fixed_miss());
  testing::add_rect(map, 20, 24, 79, 24, 6 * map.fixed_hit());  // the passage's walls (over the free cells)
  testing::add_rect(map, 20, 31, 79, 31, 6 * map.fixed_hit());
  planner::CostmapOptions co;
  co.robot_radius = 0.2;
  co.safety_margin = 0.0;
  co.unknown_is_free = true;
  const planner::Costmap costmap(map, co);
  const double x = 2.5, y = 1.4;  // in the passage, 1.5 m from either end
  ASSERT_FALSE(costmap.is_free(x, y));
  ASSERT_TRUE(costmap.is_free(x, 1.85));  // the room above, 0.45 m away through the wall
  EXPECT_FALSE(nearest_free(costmap, map, x, y, 0.5).has_value());
  EXPECT_FALSE(nearest_free(costmap, map, x, y, 1.2).has_value());  // no end of the passage within reach
  const auto start = nearest_free(costmap, map, x, y, 2.0);
  ASSERT_TRUE(start.has_value());
  // Out of the passage's end (1.5 m off) and round its wall at most.
  EXPECT_GT(std::hypot(start->x - x, start->y - y), 1.45);
}

}  // namespace
}  // namespace lookahead::exploration
