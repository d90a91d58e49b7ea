// SPDX-License-Identifier: MIT
// The stuck clock: a straight line to the goal that shrinks is progress; a shorter path
// left is progress only on a detour (or always, when asked), and its best is kept; a replan
// onto a much longer way restarts it (at most twice per goal) until the short way is back.
#include "lookahead/exploration/stuck_clock.hpp"

#include <gtest/gtest.h>

namespace lookahead::exploration {
namespace {

// A ring corridor: the goal 14 m away, 40 m of path. The robot drives 0.2 m/s away from the
// goal for 10 s, 20 s across, then towards it; the clock is asked once a second.
bool stuck_on_the_ring(const StuckClockOptions& o) {
  StuckClock clock(o);
  clock.start(0.0, 14.0, 40.0, 0.0);
  for (int t = 1; t <= 90; ++t) {
    const double driven = 0.2 * t;
    const double distance = t <= 10 ? 14.0 + 0.2 * t : t <= 30 ? 16.0 : 16.0 - 0.2 * (t - 30);
    if (clock.stuck(t, distance, 40.0 - driven, driven)) return true;
  }
  return false;
}

TEST(StuckClock, ARingCorridorIsProgressOnlyWhenThePathCounts) {
  EXPECT_TRUE(stuck_on_the_ring({30.0, false, false}));  // no closer than 14 m for 41 s
  EXPECT_FALSE(stuck_on_the_ring({30.0, false, true}));  // a detour: the path left shrinks
  EXPECT_FALSE(stuck_on_the_ring({30.0, true, false}));
}

// A door the margin flickers on: the goal 2 m away, replans give paths of 3-5 m at random,
// the robot does not move. Counting their shortening as progress would keep the goal.
TEST(StuckClock, ShortReplansInADoorAreNoDetour) {
  for (const bool along : {false, true}) {
    StuckClock clock({30.0, along, true});
    clock.start(0.0, 2.0, 5.0, 0.0);
    bool stuck = false;
    int t = 1;
    for (; t <= 60 && !stuck; ++t) stuck = clock.stuck(t, 2.0, 5.0 - 0.05 * (t % 40), 0.0);
    if (along) {
      EXPECT_FALSE(stuck);  // 5 m -> 3.05 m over 39 s: always a new best
    } else {
      EXPECT_TRUE(stuck);
      EXPECT_EQ(t - 1, 31);  // after stuck_time, as without any path rule
    }
  }
}

TEST(StuckClock, TheBestPathIsKeptAcrossReplans) {
  StuckClock clock({30.0, false, true});
  clock.start(0.0, 10.0, 30.0, 0.0);
  EXPECT_FALSE(clock.stuck(10.0, 10.5, 27.0, 3.0));  // progress along the detour
  // A replan swaps to a longer route and back: 29 m, then 27.1 m is no new best.
  EXPECT_FALSE(clock.stuck(20.0, 10.5, 29.0, 5.0));
  EXPECT_FALSE(clock.stuck(35.0, 10.5, 27.1, 8.0));
  EXPECT_TRUE(clock.stuck(41.0, 10.5, 27.1, 9.0));
  EXPECT_DOUBLE_EQ(clock.driven_since_progress(9.0), 6.0);
}

TEST(StuckClock, CountingThePathAlwaysAppliesFromThen) {
  StuckClock clock({30.0, false, false});
  clock.start(0.0, 2.0, 8.0, 0.0);
  EXPECT_FALSE(clock.stuck(20.0, 2.0, 7.0, 1.0));
  clock.count_path_always();
  EXPECT_FALSE(clock.stuck(31.0, 2.0, 6.5, 2.0));  // 6.5 < 7.8: progress from 8 m
  EXPECT_FALSE(clock.stuck(60.0, 2.0, 6.5, 2.0));
  EXPECT_TRUE(clock.stuck(62.0, 2.0, 6.5, 2.0));
}

// The way through a room's unknown side ends at a wall the robot sees from inside: 6.5 m
// were left, the replan goes round through the door, 9.5 m. Driving it leads away from the
// goal (3.5 m -> 5 m -> 3.5 m in a straight line) while its path left shrinks.
bool stuck_round_the_door(bool forced) {
  StuckClock clock({30.0, false, true});
  clock.start(0.0, 3.5, 6.5, 0.0);
  EXPECT_FALSE(clock.stuck(2.0, 3.2, 6.2, 0.3));
  if (forced) EXPECT_EQ(clock.replanned(3.0, 3.6, 9.5, 6.5, 0.5), StuckClock::Replan::kForcedDetour);
  for (int t = 4; t <= 45; ++t) {
    const double driven = 0.5 + 0.2 * (t - 3);
    const double distance = t <= 20 ? 3.6 + 0.08 * (t - 3) : 5.0 - 0.06 * (t - 20);
    if (clock.stuck(t, distance, 9.5 - 0.2 * (t - 3), driven)) return true;
  }
  return false;
}

TEST(StuckClock, AForcedDetourRestartsTheClockAndItsPathCounts) {
  EXPECT_TRUE(stuck_round_the_door(false));  // 9.5 m is no detour by the 10 m rule
  EXPECT_FALSE(stuck_round_the_door(true));
}

TEST(StuckClock, ASwapBetweenSimilarWaysIsNoForcedDetour) {
  StuckClock clock({30.0, false, true});
  clock.start(0.0, 8.0, 13.7, 0.0);
  EXPECT_EQ(clock.replanned(5.0, 8.0, 15.2, 13.7, 1.0), StuckClock::Replan::kSameWay);  // 15.2 < 1.2 x 13.7 + 1
  EXPECT_TRUE(clock.stuck(31.0, 8.0, 14.0, 2.0));
}

// A door the margin flickers on: the short way (7 m) closes, the way round (11 m) restarts
// the clock, the short way opens again: the robot is measured as if it had never left it.
TEST(StuckClock, TheShortWayBackUndoesTheRestart) {
  StuckClock clock({30.0, false, true});
  clock.start(0.0, 5.0, 7.0, 0.0);
  EXPECT_EQ(clock.replanned(20.0, 5.0, 11.0, 7.0, 1.0), StuckClock::Replan::kForcedDetour);
  EXPECT_FALSE(clock.stuck(31.0, 5.0, 10.5, 1.5));  // restarted at 20 s, and 10.5 m is progress
  EXPECT_EQ(clock.replanned(33.0, 5.0, 7.0, 10.5, 1.8), StuckClock::Replan::kWayBackOpened);
  EXPECT_TRUE(clock.stuck(34.0, 5.0, 7.0, 2.0));  // no progress since 0 s
}

TEST(StuckClock, AtMostTwoForcedDetoursPerGoal) {
  using R = StuckClock::Replan;
  StuckClock clock({30.0, false, true});
  clock.start(0.0, 3.0, 5.0, 0.0);
  EXPECT_EQ(clock.replanned(10.0, 3.0, 8.0, 5.0, 1.0), R::kForcedDetour);
  EXPECT_EQ(clock.replanned(20.0, 3.0, 12.0, 7.0, 2.0), R::kForcedDetour);
  EXPECT_EQ(clock.replanned(30.0, 3.0, 16.0, 10.0, 3.0), R::kSameWay);
  EXPECT_TRUE(clock.stuck(51.0, 3.0, 16.0, 3.0));  // 31 s after the second restart
  clock.start(60.0, 3.0, 5.0, 3.0);                // a new goal gets its two again
  EXPECT_EQ(clock.replanned(61.0, 3.0, 8.0, 5.0, 3.0), R::kForcedDetour);
}

}  // namespace
}  // namespace lookahead::exploration
