// SPDX-License-Identifier: MIT
// An exploration mission: a simulated robot explores a world until it is mapped. Each step
// is one laser period: sense (scan and odometry into the RBPF, or into a map at the true
// pose), refresh (costmap, frontiers, path validity), decide (the navigation state machine,
// navigation_state_machine.hpp), act (pure pursuit -> unicycle, collisions checked against
// the true world), record.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "lookahead/exploration/breadcrumbs.hpp"
#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"
#include "lookahead/exploration/lookahead_mapping.hpp"
#include "lookahead/exploration/mission_metrics.hpp"
#include "lookahead/exploration/mission_options.hpp"
#include "lookahead/exploration/navigation_state_machine.hpp"
#include "lookahead/exploration/prediction_attempts.hpp"
#include "lookahead/exploration/prediction_targets.hpp"
#include "lookahead/exploration/reactive_stop.hpp"
#include "lookahead/exploration/recovery_behaviour.hpp"
#include "lookahead/exploration/stop_escape.hpp"
#include "lookahead/exploration/stuck_clock.hpp"
#include "lookahead/exploration/target_selection.hpp"
#include "lookahead/exploration/target_strategy.hpp"
#include "lookahead/exploration/world.hpp"
#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path_follower.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"

namespace lookahead::exploration {

class RunLog;

enum class MissionStatus {
  kRunning,
  kCoverageReached,  ///< the coverage goal was met
  kDone,             ///< no reachable frontier is left
  kTrapped,          ///< frontiers are left but the robot cannot get to any of them
  kTimeLimit,        ///< the simulated time limit was reached
  kCollision,        ///< the robot touched a wall of the true world: a failure
};
const char* to_string(MissionStatus status);

struct MissionStatistics {
  int selections = 0, plans = 0, plan_failures = 0, replans = 0, stuck_goals = 0, grid_fallbacks = 0;
  double planning_time = 0.0;  ///< wall clock [s]
  int collisions = 0;
  int safety_stops = 0;  ///< steps the reactive stop held the robot
  int stop_escapes = 0;  ///< turn-then-creep escapes from a lasting stop (stop_escape.hpp)
  int backtracks = 0;    ///< escapes along the robot's own trail (no frontier was reachable)
  int squeezes = 0;      ///< paths planned without the safety margin
  int kept_paths = 0;    ///< paths the margin closed, kept while the body fits (the replan went the long way or failed)
  int forgiven_goals = 0;                  ///< goals blacklisted for good, retried before "trapped"
  std::size_t retired_frontier_cells = 0;  ///< frontier cells that outlived a visit
  std::size_t scans = 0, map_refreshes = 0;
  /// Simulated time [s] a selection first found every frontier left predicted (P-SLAM's end
  /// of exploration, sec. V-A.1; the mission goes on to observe them); -1: never.
  double rest_predicted_time = -1.0;
};

class Mission {
 public:
  Mission(const World& world, const slam::Pose2& start, const MissionOptions& options);
  ~Mission();

  /// Writes the simulated run as a log `lookahead slam` replays: a ROS1 bag for a .bag path,
  /// else a CARMEN log (ODOM + FLASER).
  void record_log(const std::string& path);
  /// One laser period. Returns the status after it.
  MissionStatus step();
  /// Steps until the mission ends; `every_second` is called once per simulated second.
  MissionStatus run(const std::function<void(const Mission&)>& every_second = nullptr);

  [[nodiscard]] MissionStatus status() const { return status_; }
  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] double path_length() const { return path_length_; }
  [[nodiscard]] double coverage() const { return curve_.empty() ? 0.0 : curve_.back().coverage; }
  [[nodiscard]] const slam::OccupancyGrid& map() const;
  /// What the laser observed, inserted at the true pose: coverage counts its free cells.
  /// The robot's map() itself under pose_source truth.
  [[nodiscard]] const slam::OccupancyGrid& observed_map() const { return truth_map_; }
  [[nodiscard]] slam::Pose2 estimate() const;
  [[nodiscard]] const slam::Pose2& truth() const { return robot_.pose(); }
  [[nodiscard]] const std::vector<slam::Pose2>& true_path() const { return true_path_; }
  [[nodiscard]] const std::vector<slam::Pose2>& estimated_path() const { return estimated_path_; }
  [[nodiscard]] const std::vector<CoverageSample>& coverage_curve() const { return curve_; }
  [[nodiscard]] const FrontierDetector& frontiers() const { return frontiers_; }
  [[nodiscard]] const std::optional<planner::Point2>& goal() const { return goal_; }
  [[nodiscard]] const planner::Path* current_path() const { return follower_ ? &follower_->path() : nullptr; }
  /// Where the robot started a turn-then-creep escape from a lasting stop (map.png marks them).
  [[nodiscard]] const std::vector<planner::Point2>& escape_spots() const { return escape_spots_; }
  [[nodiscard]] const MissionStatistics& statistics() const { return stats_; }
  /// Where the navigation state machine stands (navigation_state_machine.hpp).
  [[nodiscard]] NavState navigation_state() const { return nav_state_; }
  [[nodiscard]] const ReachableArea& reachable() const { return reachable_; }
  [[nodiscard]] const CoverageMeter& coverage_meter() const { return meter_; }
  [[nodiscard]] const World& world() const { return world_; }
  [[nodiscard]] const MissionOptions& options() const { return options_; }
  [[nodiscard]] const slam::Pose2& start() const { return start_; }
  [[nodiscard]] const slam::Rbpf* slam() const { return rbpf_.get(); }
  /// The look-ahead mapping (predictions), null when it is off.
  [[nodiscard]] const LookaheadMapping* lookahead() const { return lookahead_.get(); }
  /// The look-ahead skip rule: the options' rule with the world's extent as the known boundary
  /// when asked, and wall gaps no wider than the robot.
  [[nodiscard]] SkipRule skip_rule() const;

 private:
  void sense();
  void deliver_prediction();
  std::vector<std::pair<double, double>> prediction_targets(double goal_x, double goal_y);
  void predict_while_idle();  ///< LookaheadOptions::predict_while_idle
  void refresh();
  void decide();  ///< runs the navigation state machine (mission_navigation.cpp)
  NavEvent step_state();
  NavEvent look_around_step();
  NavEvent select_step();
  NavEvent follow_step();
  NavEvent replan_step();
  NavEvent recover_step();
  void goal_reached();  ///< a reached goal's bookkeeping
  bool replan_current_goal();
  SelectionInputs selection_inputs();
  void count(const Selection& s);
  void act();
  void hold_at_stop();  ///< the reactive stop held the robot this step
  [[nodiscard]] EscapeLimits escape_limits() const;
  void record();
  void check_end();
  bool goal_still_useful() const;
  bool goal_predicted() const;  ///< look-ahead mapping covers the current target
  // The moves of the recovery behaviours (RecoveryActions, mission_escapes.cpp).
  class Actions;
  bool backtrack();                                 ///< follows the trail out of a place with no reachable frontier
  bool squeeze();                                   ///< plans to a frontier on the map inflated by the body alone
  std::size_t forgive_blacklist();                  ///< goals blacklisted for good are retried, progress along the path
  planner::Costmap body_costmap() const;            ///< the map inflated by the body, no safety margin
  planner::FollowerOptions close_tracking() const;  ///< for paths that fit only where drawn
  void follow(const Selection& s, const planner::FollowerOptions& tracking);  ///< a new goal and path
  void escaped();  ///< out of a trap: the recovery behaviours' counts start again

  const World& world_;
  MissionOptions options_;
  slam::Pose2 start_;
  Robot robot_;
  LaserSimulator laser_;
  OdometryModel odometry_;
  std::unique_ptr<slam::Rbpf> rbpf_;
  /// Every scan inserted at the true pose: the robot's map under pose_source truth, and
  /// under slam the record of what the laser observed, which coverage counts.
  slam::OccupancyGrid truth_map_;
  ReachableArea reachable_;
  CoverageMeter meter_;
  FrontierDetector frontiers_;
  GoalBlacklist blacklist_;
  GoalBlacklist replan_failures_;  ///< goals given up once because no replan reached them
  StuckClock stuck_clock_;         ///< gives the current goal up when the robot makes no progress
  std::unique_ptr<TargetStrategy> strategy_;
  std::unique_ptr<LookaheadMapping> lookahead_;
  PredictionAttempts predicted_targets_;  ///< frontier goals predicted lately (predict_while_idle)
  double next_idle_prediction_ = 0.0;
  planner::Costmap costmap_;
  std::unique_ptr<planner::PathFollower> follower_;
  /// The current path is checked with the body alone: the safety margin closed it, and the
  /// replan would have taken the long way round (a door the margin flickers on) or swapped
  /// back after the robot already went round once (went_round_).
  bool kept_on_body_ = false;
  /// Since its goal was chosen, a path the margin closed was once replaced by another way
  /// round: later paths the margin closes on the way to that goal are kept.
  bool went_round_ = false;
  /// A path the margin closed while the body still fits along it: the replan decides.
  std::unique_ptr<planner::PathFollower> margin_blocked_;
  std::optional<planner::Point2> goal_;
  /// A goal reached with its frontier still there: retired after the next map update.
  std::optional<planner::Point2> reached_goal_;
  Breadcrumbs crumbs_;
  bool backtracking_ = false;  ///< the current goal is the end of a backtrack, not a frontier
  bool squeezing_ = false;     ///< the current path was planned without the safety margin
  /// Since the last squeeze the robot has not stood on a cell the safety margin leaves free.
  bool tight_ = false;
  std::unique_ptr<RunLog> log_;
  slam::LaserScan last_scan_;

  MissionStatus status_ = MissionStatus::kRunning;
  MissionStatistics stats_;
  double time_ = 0.0, path_length_ = 0.0, turned_ = 0.0;
  double next_goal_check_ = 0.0, next_metrics_ = 0.0;
  NavState nav_state_ = NavState::kLookAround;
  std::vector<std::unique_ptr<RecoveryBehaviour>> recoveries_;  ///< in the order they are tried
  int unreachable_streak_ = 0;                                  ///< failed selections in a row
  bool last_unreachable_ = false;  ///< the last failed selection found no path to a frontier goal
  ReactiveStop stop_;
  StopEscape escape_;  ///< turn-then-creep out of a corner the stop holds the robot at
  std::vector<planner::Point2> escape_spots_;
  bool map_changed_ = false;
  bool visiting_predicted_ = false;  ///< the goal was chosen with every frontier predicted
  bool path_blocked_ = false;        ///< the follower was dropped because new walls block its path
  double blocked_rest_ = -1.0;       ///< [m] left of the path a block dropped; < 0: none
  std::size_t last_resamplings_ = 0, last_best_ = 0;
  slam::Pose2 last_refresh_pose_;
  /// Where scans went into the map since the last refresh: the bounding box of their poses.
  struct SensedPoses {
    planner::Point2 lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
    void add(const slam::Pose2& p) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    [[nodiscard]] bool empty() const { return lo.x > hi.x; }
  } sensed_;
  std::vector<slam::Pose2> true_path_, estimated_path_;
  std::vector<CoverageSample> curve_;
};

}  // namespace lookahead::exploration
