// SPDX-License-Identifier: MIT
// One target selection of a mission: price every frontier cluster (travel cost by Dijkstra
// on the costmap, information gain on the map), let the strategy rank them, and plan to the
// best one that the planner can reach; failed goals go on the blacklist.
#pragma once

#include <optional>
#include <string>

#include "lookahead/exploration/breadcrumbs.hpp"
#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"
#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/target_strategy.hpp"
#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/plan.hpp"

namespace lookahead::exploration {

enum class SelectionOutcome {
  kPlanned,      ///< a target and a path to it
  kNoFrontier,   ///< no frontier with a goal is left: done
  kUnreachable,  ///< frontiers exist, but none can be reached, or all reachable ones were
                 ///< visited without clearing them: trapped
  kPlanFailed,   ///< reachable frontiers exist, but the planner found no path this time
};

struct Selection {
  SelectionOutcome outcome = SelectionOutcome::kNoFrontier;
  double goal_x = 0.0, goal_y = 0.0;
  planner::Path path;
  int plans = 0, plan_failures = 0;
  int grid_fallbacks = 0;      ///< paths taken from the Dijkstra price when OMPL found none
  double planning_time = 0.0;  ///< [s], summed over the attempts
  std::size_t clusters = 0, candidates = 0;
  /// The strategy skipped every reachable frontier as predicted; the target is one of them.
  bool rest_predicted = false;
  /// kUnreachable only because every reachable frontier is blacklisted for a while: worth
  /// waiting for the entries to expire, not a trap.
  bool waiting_on_blacklist = false;
};

struct SelectionInputs {
  const slam::OccupancyGrid* map = nullptr;
  const planner::Costmap* costmap = nullptr;
  const FrontierDetector* frontiers = nullptr;
  const TargetStrategy* strategy = nullptr;
  GoalBlacklist* blacklist = nullptr;
  slam::Pose2 pose;
  double now = 0.0;
  double sensor_range = 8.0;
  int max_attempts = 5;
  planner::PlannerOptions planner;
  /// The look-ahead map, for strategies that use predictions (null: none).
  const PredictedMap* predicted = nullptr;
  SkipRule skip{};  ///< when the look-ahead map covers a frontier
  /// The robot's body [m] (no safety margin): a backtrack's shortcut between two passes of
  /// the trail keeps this clear of occupied cells.
  double robot_radius = 0.0;
};

Selection select_target(const SelectionInputs& in);

/// A new path to the current goal when the old one got blocked (new walls on it): keeps the
/// target, so a blocked path does not turn into a new choice. kPlanned or kPlanFailed.
Selection replan_to_goal(const SelectionInputs& in, const planner::Point2& goal);

/// The way out when no frontier can be reached from the robot's place on the costmap: the
/// robot's own trail back to its last crumb on a free cell outside that place (the robot's
/// region on the costmap, from its nearest free cell), the shortest way along the trail
/// (passes joined where the map has no occupied cell between them). kPlanned with the goal
/// at that crumb (the newer crumbs are popped), or kUnreachable when no crumb lies outside.
Selection select_escape(const SelectionInputs& in, Breadcrumbs& crumbs);

/// The free cell of `costmap` nearest to (x, y) within `radius` that the robot can get to
/// from there without crossing a wall of `map` (a robot brushing a wall, or in a passage
/// the safety margin closes, sits in the inflation zone); nullopt when there is none.
/// Cells count as open when `map` knows them below the costmap's occupied threshold.
std::optional<planner::Point2> nearest_free(const planner::Costmap& costmap, const slam::OccupancyGrid& map, double x,
                                            double y, double radius);

}  // namespace lookahead::exploration
