// SPDX-License-Identifier: MIT
// The mission's decision step: the navigation state machine (navigation_state_machine.hpp)
// driving target selection, path following, replanning and the recovery behaviours
// (recovery_behaviour.hpp). Each state's step reports one event; the table says where it
// leads.
#include <spdlog/spdlog.h>

#include <cmath>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/target_selection.hpp"

namespace lookahead::exploration {
namespace {

// Selections in a row with no reachable frontier (each followed by a backtrack or a look
// around) before the last resorts (recovery_behaviour.hpp).
constexpr int kOrdinaryTries = 3;

// A replan longer than this many times the blocked path's rest, plus the slack [m], turns
// the robot the long way round. When the safety margin alone closed the blocked path (a
// door it closes with one scan and opens with the next), the path is kept instead: taking
// such replans swaps the robot between two ways round for as long as the door flickers.
constexpr double kLongWayRound = 1.5;
constexpr double kLongWayRoundSlack = 1.0;

bool long_way_round(const planner::Path& replanned, const planner::PathFollower& blocked) {
  return planner::path_length(replanned) > kLongWayRound * blocked.remaining_length() + kLongWayRoundSlack;
}

// A replan this much longer than the blocked path's rest [m] is another way round, not the
// same way past a flickering cell.
bool other_way_round(const planner::Path& replanned, double blocked_rest) {
  return planner::path_length(replanned) > blocked_rest + kLongWayRoundSlack;
}

}  // namespace

void Mission::decide() {
  if (costmap_.empty()) return;
  for (;;) {
    const NavEvent event = step_state();
    if (event == NavEvent::kNone) return;
    const NavState next = next_state(nav_state_, event);
    spdlog::trace("t {:.1f}: {} --{}--> {}", time_, to_string(nav_state_), to_string(event), to_string(next));
    nav_state_ = next;
    if (resting(nav_state_)) return;
  }
}

NavEvent Mission::step_state() {
  switch (nav_state_) {
    case NavState::kLookAround:
      return look_around_step();
    case NavState::kSelectTarget:
      return select_step();
    case NavState::kFollow:
      return follow_step();
    case NavState::kReplan:
      return replan_step();
    case NavState::kRecover:
      return recover_step();
    case NavState::kDone:
      return NavEvent::kNone;
  }
  return NavEvent::kNone;
}

NavEvent Mission::look_around_step() {
  return turned_ < options_.initial_turn ? NavEvent::kNone : NavEvent::kLookedAround;
}

void Mission::goal_reached() {
  // A reached goal whose frontier is still there cannot be explored from there (a corner
  // the sensor cannot see from its goal, the inside of a wall): the frontier cells next to
  // it are retired, and the spot is not picked again for a while.
  if (squeezing_) escaped();  // it got through: the next trap gets all its tries
  if (goal_ && !backtracking_) {
    blacklist_.add(goal_->x, goal_->y, time_);
    reached_goal_ = goal_;  // its frontier gets one more map update to clear
  }
}

NavEvent Mission::follow_step() {
  // Refresh and the reactive stop drop the follower when new walls block its path.
  if (!follower_) return path_blocked_ ? NavEvent::kPathBlocked : NavEvent::kGoalDropped;
  if (follower_->goal_reached()) {
    goal_reached();
    return NavEvent::kGoalReached;
  }
  if (time_ < next_goal_check_) return NavEvent::kNone;
  next_goal_check_ = time_ + options_.goal_check_period;
  const slam::Pose2 p = estimate();
  const double d = std::hypot(goal_->x - p.x, goal_->y - p.y);
  // A path around a wall can lead away from the goal for long: the stuck clock counts a
  // shorter path left as progress on a detour (stuck_clock.hpp).
  if (stuck_clock_.stuck(time_, d, follower_->remaining_length(), path_length_)) {
    spdlog::debug(
        "t {:.1f}: stuck on ({:.2f}, {:.2f}): {:.2f} m away, {:.2f} m of path left, {:.2f} m driven since "
        "the last progress{}{}",
        time_, goal_->x, goal_->y, d, follower_->remaining_length(), stuck_clock_.driven_since_progress(path_length_),
        squeezing_ ? ", squeezing" : "", backtracking_ ? ", backtracking" : "");
    blacklist_.add(goal_->x, goal_->y, time_);
    ++stats_.stuck_goals;
    return NavEvent::kStuck;
  }
  if (!goal_still_useful()) return NavEvent::kGoalExplored;
  return goal_predicted() ? NavEvent::kGoalPredicted : NavEvent::kNone;
}

NavEvent Mission::replan_step() {
  // A blocked path is no reason to change the target: only a target that stopped being
  // worth it is. Re-choosing on every blocked path swaps between far frontiers.
  if (!goal_ || !goal_still_useful()) return NavEvent::kGoalDropped;
  if (replan_current_goal()) return NavEvent::kReplanned;
  // No way to the goal any more. The map often lets it back a moment later, and a new
  // selection resets the stuck clock, so two such goals could take turns for good: a spot
  // whose replan fails a second time within the blacklist lifetime is a failed goal. Once
  // is not: a door the margin flickers on closes a path for a moment only.
  if (!backtracking_) {
    if (replan_failures_.contains(goal_->x, goal_->y, time_))
      blacklist_.add(goal_->x, goal_->y, time_);
    else
      replan_failures_.add(goal_->x, goal_->y, time_);
  }
  return NavEvent::kReplanFailed;
}

bool Mission::replan_current_goal() {
  path_blocked_ = false;
  std::unique_ptr<planner::PathFollower> blocked = std::move(margin_blocked_);
  const double blocked_rest = blocked_rest_;
  blocked_rest_ = -1.0;
  const Selection s = replan_to_goal(selection_inputs(), *goal_);
  count(s);
  const bool planned = s.outcome == SelectionOutcome::kPlanned;
  // One way round per goal: in a room with two narrow doors the margin closes whichever
  // door the robot walks up to, and a replan through the other, taken each time, sends the
  // robot to and fro between them until the time limit. After the first swap the robot
  // stays on the way it took; the body still guards the kept path, and the stuck clock the
  // goal.
  const bool keep = blocked && (!planned || went_round_ || long_way_round(s.path, *blocked));
  if (blocked && planned && !keep && other_way_round(s.path, blocked_rest)) went_round_ = true;
  spdlog::debug("t {:.1f}: replan to ({:.2f}, {:.2f}): {}{}", time_, goal_->x, goal_->y, planned ? "planned" : "failed",
                keep ? "; the path the margin closed is kept" : "");
  // The stuck clock keeps running: a goal that keeps getting blocked is given up in time.
  if (keep) {
    follower_ = std::move(blocked);
    kept_on_body_ = true;
    ++stats_.kept_paths;
    escape_.arm();
    return true;
  }
  if (!planned) return false;
  follower_ = std::make_unique<planner::PathFollower>(s.path, options_.follower);
  kept_on_body_ = false;
  escape_.arm();
  if (blocked_rest >= 0.0) {
    const slam::Pose2 p = estimate();
    const double length = planner::path_length(s.path);
    const StuckClock::Replan r =
        stuck_clock_.replanned(time_, std::hypot(goal_->x - p.x, goal_->y - p.y), length, blocked_rest, path_length_);
    if (r != StuckClock::Replan::kSameWay)
      spdlog::debug("t {:.1f}: {} ({:.2f} m; the blocked path had {:.2f} m left)", time_,
                    r == StuckClock::Replan::kForcedDetour ? "a forced detour restarts the stuck clock"
                                                           : "the short way is back: the restart is undone",
                    length, blocked_rest);
  }
  return true;
}

NavEvent Mission::select_step() {
  path_blocked_ = false;
  backtracking_ = false;
  squeezing_ = false;
  visiting_predicted_ = false;
  follower_.reset();
  margin_blocked_.reset();
  blocked_rest_ = -1.0;
  goal_.reset();
  blacklist_.expire(time_);
  // Half through a door the margin closes, the ordinary costmap has no room where the robot
  // stands: the next target is chosen as the squeeze chose its own. Out of the door, the
  // margin has room again.
  if (tight_) {
    const slam::Pose2 p = estimate();
    tight_ = !costmap_.is_free(p.x, p.y);
    if (tight_ && squeeze()) return NavEvent::kSqueezed;
  }
  // How right the predictions this choice reads are (the simulator knows the world).
  if (lookahead_ && strategy_->prediction_use() != PredictionUse::kNone) lookahead_->score_choice(map());
  const Selection s = select_target(selection_inputs());
  spdlog::debug("t {:.1f}: selection {}: clusters {}, candidates {}, plans {} ({} failed), goal ({:.2f}, {:.2f})",
                time_, static_cast<int>(s.outcome), s.clusters, s.candidates, s.plans, s.plan_failures, s.goal_x,
                s.goal_y);
  ++stats_.selections;
  count(s);
  if (s.outcome == SelectionOutcome::kNoFrontier) {
    status_ = MissionStatus::kDone;
    return NavEvent::kNoFrontier;
  }
  if (s.outcome != SelectionOutcome::kPlanned) {
    // Frontiers that are only blacklisted for a while are no trap: the robot looks around
    // until an entry expires (each spot is retried at most max_strikes times).
    if (s.waiting_on_blacklist) {
      turned_ = 0.0;
      return NavEvent::kWaitOnBlacklist;
    }
    ++unreachable_streak_;
    last_unreachable_ = s.outcome == SelectionOutcome::kUnreachable;
    return NavEvent::kNoPath;
  }
  unreachable_streak_ = 0;
  escaped();
  visiting_predicted_ = s.rest_predicted;
  if (s.rest_predicted && stats_.rest_predicted_time < 0) stats_.rest_predicted_time = time_;
  // P-SLAM predicts the region around the next exploration goal (sec. II-A, step 1).
  if (lookahead_) lookahead_->request(map(), prediction_targets(s.goal_x, s.goal_y), time_);
  follow(s, options_.follower);
  return NavEvent::kPlanned;
}

void Mission::escaped() {
  for (const auto& r : recoveries_) r->escaped();
}

class Mission::Actions final : public RecoveryActions {
 public:
  explicit Actions(Mission& m) : m_(m) {}
  bool backtrack() override { return m_.backtrack(); }
  bool squeeze() override { return m_.squeeze(); }
  std::size_t forgive_blacklist() override { return m_.forgive_blacklist(); }
  void look_around() override { m_.turned_ = 0.0; }

 private:
  Mission& m_;
};

NavEvent Mission::recover_step() {
  // Maybe only for now: retrace the trail out of here, or turn once more to look around,
  // and after kOrdinaryTries failed selections the last resorts, then the second chance.
  Actions actions(*this);
  const RecoveryContext context{last_unreachable_, unreachable_streak_, kOrdinaryTries};
  switch (recover(recoveries_, context, actions)) {
    case RecoveryOutcome::kFollowing:
      return NavEvent::kRecovered;
    case RecoveryOutcome::kStartOver:
      unreachable_streak_ = 0;
      escaped();
      return NavEvent::kLookAgain;
    case RecoveryOutcome::kLookingAround:
      return NavEvent::kLookAgain;
    case RecoveryOutcome::kFailed:
      break;
  }
  status_ = MissionStatus::kTrapped;
  return NavEvent::kExhausted;
}

void Mission::follow(const Selection& s, const planner::FollowerOptions& tracking) {
  goal_ = planner::Point2{s.goal_x, s.goal_y};
  follower_ = std::make_unique<planner::PathFollower>(s.path, tracking);
  kept_on_body_ = false;
  went_round_ = false;
  escape_.arm();
  const slam::Pose2 p = estimate();
  stuck_clock_.start(time_, std::hypot(s.goal_x - p.x, s.goal_y - p.y), planner::path_length(s.path), path_length_);
  next_goal_check_ = time_ + options_.goal_check_period;
}

}  // namespace lookahead::exploration
