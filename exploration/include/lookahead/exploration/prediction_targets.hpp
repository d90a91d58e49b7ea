// SPDX-License-Identifier: MIT
// Which frontiers the look-ahead mapping predicts (Chang et al. 2007, sec. II-A, step 1: the
// target cell f is "the next possible exploration goal"; the prediction "can be easily
// extended to predict several possible targets"). At a selection: the chosen goal, then the
// nearest other frontier goals. While the predictor is idle (opt-in): the nearest frontier
// goals that no hypothesis covers yet and that were not tried lately, so that the next
// selection already knows which frontiers are predicted.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/prediction_attempts.hpp"
#include "lookahead/planner/costmap.hpp"
#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::exploration {

using TargetList = std::vector<std::pair<double, double>>;

/// How far the robot is from a frontier's goal [m]; infinity: no way there.
using GoalDistance = std::function<double(const FrontierCluster&)>;

/// The straight-line distance from `robot` (the default order of the targets).
GoalDistance straight_line_from(const slam::Pose2& robot);

/// The chosen goal first, then the other frontier goals (more than 1 m from it) nearest to
/// `robot` first, `count` in all.
TargetList selection_targets(const std::vector<FrontierCluster>& clusters, double goal_x, double goal_y,
                             const slam::Pose2& robot, int count);
/// The same, nearest by `distance` first; goals at infinite distance are left out.
TargetList selection_targets(const std::vector<FrontierCluster>& clusters, double goal_x, double goal_y,
                             const GoalDistance& distance, int count);

/// Frontier goals worth a prediction while the predictor has nothing to do: not covered by
/// the look-ahead map under `rule` (covered_share below `skip_share`) and not tried lately
/// (`tried`: a spot is tried again once its surroundings grew); nearest to `robot` first,
/// `count` at most.
TargetList unpredicted_frontier_targets(const std::vector<FrontierCluster>& clusters, const slam::OccupancyGrid& map,
                                        const PredictedMap& predicted, const SkipRule& rule, double skip_share,
                                        const PredictionAttempts& tried, double now, const slam::Pose2& robot,
                                        int count);
/// The same, nearest by `distance` first; goals at infinite distance are left out.
TargetList unpredicted_frontier_targets(const std::vector<FrontierCluster>& clusters, const slam::OccupancyGrid& map,
                                        const PredictedMap& predicted, const SkipRule& rule, double skip_share,
                                        const PredictionAttempts& tried, double now, const GoalDistance& distance,
                                        int count);

/// Whether a goal on the way serves only predicted frontiers: there is a frontier whose goal
/// lies within `radius` of (x, y), and every such frontier is `covered`. Frontiers can share
/// a goal spot; one of them left open keeps the goal, or the next selection would choose the
/// same spot again for it.
bool goal_serves_only_predicted(const std::vector<FrontierCluster>& clusters, double x, double y, double radius,
                                const std::function<bool(const FrontierCluster&)>& covered);

}  // namespace lookahead::exploration
