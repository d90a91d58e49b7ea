// SPDX-License-Identifier: MIT
// The navigation state machine's table and the recovery behaviours' order and rules.
#include "lookahead/exploration/navigation_state_machine.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "lookahead/exploration/mission_options.hpp"
#include "lookahead/exploration/recovery_behaviour.hpp"
#include "lookahead/exploration/skip_rule.hpp"
#include "lookahead/slam/config/named_choice.hpp"

namespace lookahead::exploration {
namespace {

TEST(NavigationStateMachine, FollowsTheTable) {
  EXPECT_EQ(next_state(NavState::kLookAround, NavEvent::kLookedAround), NavState::kSelectTarget);
  EXPECT_EQ(next_state(NavState::kSelectTarget, NavEvent::kPlanned), NavState::kFollow);
  EXPECT_EQ(next_state(NavState::kSelectTarget, NavEvent::kSqueezed), NavState::kFollow);
  EXPECT_EQ(next_state(NavState::kSelectTarget, NavEvent::kNoFrontier), NavState::kDone);
  EXPECT_EQ(next_state(NavState::kSelectTarget, NavEvent::kWaitOnBlacklist), NavState::kLookAround);
  EXPECT_EQ(next_state(NavState::kSelectTarget, NavEvent::kNoPath), NavState::kRecover);
  for (NavEvent e : {NavEvent::kGoalReached, NavEvent::kStuck, NavEvent::kGoalExplored, NavEvent::kGoalPredicted,
                     NavEvent::kGoalDropped})
    EXPECT_EQ(next_state(NavState::kFollow, e), NavState::kSelectTarget) << to_string(e);
  EXPECT_EQ(next_state(NavState::kFollow, NavEvent::kPathBlocked), NavState::kReplan);
  EXPECT_EQ(next_state(NavState::kReplan, NavEvent::kReplanned), NavState::kFollow);
  EXPECT_EQ(next_state(NavState::kReplan, NavEvent::kReplanFailed), NavState::kSelectTarget);
  EXPECT_EQ(next_state(NavState::kRecover, NavEvent::kRecovered), NavState::kFollow);
  EXPECT_EQ(next_state(NavState::kRecover, NavEvent::kLookAgain), NavState::kLookAround);
  EXPECT_EQ(next_state(NavState::kRecover, NavEvent::kExhausted), NavState::kDone);
  EXPECT_EQ(next_state(NavState::kFollow, NavEvent::kNone), NavState::kFollow);
}

TEST(NavigationStateMachine, AnEventAStateCannotReportIsAnError) {
  EXPECT_THROW(next_state(NavState::kDone, NavEvent::kPlanned), std::logic_error);
  EXPECT_THROW(next_state(NavState::kFollow, NavEvent::kNoFrontier), std::logic_error);
  EXPECT_THROW(next_state(NavState::kLookAround, NavEvent::kRecovered), std::logic_error);
}

TEST(NavigationStateMachine, OnlyLookAroundFollowAndDoneRest) {
  EXPECT_TRUE(resting(NavState::kLookAround));
  EXPECT_TRUE(resting(NavState::kFollow));
  EXPECT_TRUE(resting(NavState::kDone));
  EXPECT_FALSE(resting(NavState::kSelectTarget));
  EXPECT_FALSE(resting(NavState::kReplan));
  EXPECT_FALSE(resting(NavState::kRecover));
}

// Records the moves asked for; each succeeds as configured.
struct FakeActions final : RecoveryActions {
  bool backtrack_ok = false, squeeze_ok = false;
  std::size_t forgivable = 0;
  std::vector<std::string> moves;
  bool backtrack() override {
    moves.emplace_back("backtrack");
    return backtrack_ok;
  }
  bool squeeze() override {
    moves.emplace_back("squeeze");
    return squeeze_ok;
  }
  std::size_t forgive_blacklist() override {
    moves.emplace_back("forgive");
    return forgivable;
  }
  void look_around() override { moves.emplace_back("look"); }
};

RecoveryContext failed(int selections, bool unreachable = true) { return {unreachable, selections, 3}; }

TEST(RecoveryBehaviours, OrdinaryTriesBacktrackThenLookAround) {
  const auto behaviours = make_recoveries(default_recovery_order());
  FakeActions a;
  EXPECT_EQ(recover(behaviours, failed(1), a), RecoveryOutcome::kLookingAround);  // no trail to follow
  EXPECT_EQ(a.moves, (std::vector<std::string>{"backtrack", "look"}));
  a.moves.clear();
  a.backtrack_ok = true;
  EXPECT_EQ(recover(behaviours, failed(2), a), RecoveryOutcome::kFollowing);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"backtrack"}));
  a.moves.clear();
  // Plans that failed for another reason than no way to the goal: no backtrack.
  EXPECT_EQ(recover(behaviours, failed(2, false), a), RecoveryOutcome::kLookingAround);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"look"}));
}

TEST(RecoveryBehaviours, LastResortAlternatesSqueezeAndBacktrackSixTimes) {
  const auto behaviours = make_recoveries(default_recovery_order());
  FakeActions a;
  a.squeeze_ok = a.backtrack_ok = true;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(recover(behaviours, failed(3 + i), a), RecoveryOutcome::kFollowing);
  EXPECT_EQ(a.moves,
            (std::vector<std::string>{"squeeze", "backtrack", "squeeze", "backtrack", "squeeze", "backtrack"}));
  a.moves.clear();
  // The seventh: the last resort is used up; the second chance has nothing to forgive.
  EXPECT_EQ(recover(behaviours, failed(9), a), RecoveryOutcome::kFailed);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"forgive"}));
  // Out of the trap, the last resort gets its moves again.
  for (const auto& b : behaviours) b->escaped();
  a.moves.clear();
  EXPECT_EQ(recover(behaviours, failed(3), a), RecoveryOutcome::kFollowing);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"squeeze"}));
}

TEST(RecoveryBehaviours, TheSecondChanceComesOncePerMission) {
  const auto behaviours = make_recoveries(default_recovery_order());
  FakeActions a;
  a.forgivable = 2;
  EXPECT_EQ(recover(behaviours, failed(3, false), a), RecoveryOutcome::kStartOver);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"forgive", "look"}));
  for (const auto& b : behaviours) b->escaped();  // the mission starts its counts again
  a.moves.clear();
  EXPECT_EQ(recover(behaviours, failed(3, false), a), RecoveryOutcome::kFailed);  // trapped
  EXPECT_TRUE(a.moves.empty());
}

TEST(RecoveryBehaviours, TheOrderIsTheConfiguredOne) {
  const auto behaviours = make_recoveries({RecoveryKind::kLookAround, RecoveryKind::kBacktrack});
  ASSERT_EQ(behaviours.size(), 2u);
  EXPECT_STREQ(behaviours[0]->name(), "look_around");
  FakeActions a;
  a.backtrack_ok = true;
  EXPECT_EQ(recover(behaviours, failed(1), a), RecoveryOutcome::kLookingAround);
  EXPECT_EQ(a.moves, (std::vector<std::string>{"look"}));
  const auto defaults = make_recoveries(default_recovery_order());
  std::vector<std::string> names;
  for (const auto& b : defaults) names.emplace_back(b->name());
  EXPECT_EQ(names, (std::vector<std::string>{"backtrack", "last_resort", "second_chance", "look_around"}));
}

TEST(RecoveryOrder, ParsesNamesAndRejectsUnknownOrRepeatedOnes) {
  EXPECT_EQ(parse_recovery_order("backtrack, last_resort, second_chance, look_around"), default_recovery_order());
  EXPECT_EQ(parse_recovery_order(MissionOptions{}.recovery_order), default_recovery_order());
  EXPECT_EQ(parse_recovery_order(" look_around ,backtrack"),
            (std::vector<RecoveryKind>{RecoveryKind::kLookAround, RecoveryKind::kBacktrack}));
  EXPECT_TRUE(parse_recovery_order("  ").empty());
  try {
    parse_recovery_order("backtrack, squeze");
    FAIL() << "an unknown name must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'squeze'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("recovery_order"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_recovery_order("backtrack, backtrack"), std::invalid_argument);
  EXPECT_THROW(parse_recovery_order("backtrack,"), std::invalid_argument);  // an empty entry
  MissionOptions o = MissionOptions::defaults();
  o.recovery_order = "second_chance, nope";
  EXPECT_THROW(o.validate(), std::invalid_argument);
}

// Property: any text either parses into distinct behaviours that print back to the same
// order, or throws std::invalid_argument; nothing else.
TEST(RecoveryOrder, AnyTextParsesOrThrowsInvalidArgument) {
  const std::vector<std::string> pieces = {
      "backtrack", "last_resort", "second_chance", "look_around", ",", " ", "squeeze", "", "\t", "x", "back"};
  std::mt19937 rng(7);
  for (int i = 0; i < 2000; ++i) {
    std::string text;
    const int n = static_cast<int>(rng() % 8);
    for (int k = 0; k < n; ++k) text += pieces[rng() % pieces.size()];
    try {
      const std::vector<RecoveryKind> order = parse_recovery_order(text);
      std::string printed;
      for (const RecoveryKind kind : order)
        printed += (printed.empty() ? "" : ",") + std::string(slam::config::choice_name(kind));
      EXPECT_EQ(parse_recovery_order(printed), order) << text;
      EXPECT_EQ(make_recoveries(order).size(), order.size());
    } catch (const std::invalid_argument&) {
    }
  }
}

TEST(SkipRuleBuilder, NamesEveryField) {
  const SkipRule::Extent box{-1.0, -2.0, 3.0, 4.0};
  const SkipRule r = SkipRule::region(5.0)
                         .with_min_confidence(0.7)
                         .with_region_tolerance(0.2)
                         .with_occupied(0.8)
                         .with_wall_gap(0.3)
                         .with_boundary(box)
                         .with_wall_slivers(true)
                         .with_free(0.3);
  EXPECT_EQ(r.variant, SkipVariant::kRegion);
  EXPECT_DOUBLE_EQ(r.region_radius, 5.0);
  EXPECT_DOUBLE_EQ(r.min_confidence, 0.7);
  EXPECT_DOUBLE_EQ(r.region_tolerance, 0.2);
  EXPECT_DOUBLE_EQ(r.occupied, 0.8);
  EXPECT_DOUBLE_EQ(r.wall_gap, 0.3);
  ASSERT_TRUE(r.boundary.has_value());
  EXPECT_DOUBLE_EQ(r.boundary->max_y, 4.0);
  EXPECT_TRUE(r.skip_wall_slivers);
  EXPECT_DOUBLE_EQ(r.free, 0.3);
  const SkipRule f = SkipRule::far_side();  // the rest at the defaults
  EXPECT_EQ(f.variant, SkipVariant::kFarSide);
  EXPECT_DOUBLE_EQ(f.region_radius, SkipRule{}.region_radius);
  EXPECT_FALSE(f.boundary.has_value());
}

}  // namespace
}  // namespace lookahead::exploration
