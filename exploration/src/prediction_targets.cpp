// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_targets.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "lookahead/exploration/target_selection.hpp"
#include "lookahead/exploration/travel_cost.hpp"

namespace lookahead::exploration {

namespace {

// The clusters' goals passing `keep`, nearest by `distance` first; goals with no way there
// (infinite distance) are no possible exploration goal and are left out.
template <typename Keep>
std::vector<const FrontierCluster*> nearest_first(const std::vector<FrontierCluster>& clusters,
                                                  const GoalDistance& distance, const Keep& keep) {
  std::vector<std::pair<double, const FrontierCluster*>> goals;
  for (const FrontierCluster& f : clusters) {
    if (!f.has_goal || !keep(f)) continue;
    const double d = distance(f);
    if (std::isfinite(d)) goals.push_back({d, &f});
  }
  std::sort(goals.begin(), goals.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const FrontierCluster*> out;
  for (const auto& g : goals) out.push_back(g.second);
  return out;
}

}  // namespace

GoalDistance straight_line_from(const slam::Pose2& robot) {
  return [robot](const FrontierCluster& f) { return std::hypot(f.goal_x - robot.x, f.goal_y - robot.y); };
}

TargetList selection_targets(const std::vector<FrontierCluster>& clusters, double goal_x, double goal_y,
                             const slam::Pose2& robot, int count) {
  return selection_targets(clusters, goal_x, goal_y, straight_line_from(robot), count);
}

TargetList selection_targets(const std::vector<FrontierCluster>& clusters, double goal_x, double goal_y,
                             const GoalDistance& distance, int count) {
  TargetList targets{{goal_x, goal_y}};
  const auto other = [&](const FrontierCluster& f) { return std::hypot(f.goal_x - goal_x, f.goal_y - goal_y) >= 1.0; };
  for (const FrontierCluster* f : nearest_first(clusters, distance, other)) {
    if (static_cast<int>(targets.size()) >= count) break;
    targets.push_back({f->goal_x, f->goal_y});
  }
  return targets;
}

TargetList unpredicted_frontier_targets(const std::vector<FrontierCluster>& clusters, const slam::OccupancyGrid& map,
                                        const PredictedMap& predicted, const SkipRule& rule, double skip_share,
                                        const PredictionAttempts& tried, double now, const slam::Pose2& robot,
                                        int count) {
  return unpredicted_frontier_targets(clusters, map, predicted, rule, skip_share, tried, now, straight_line_from(robot),
                                      count);
}

TargetList unpredicted_frontier_targets(const std::vector<FrontierCluster>& clusters, const slam::OccupancyGrid& map,
                                        const PredictedMap& predicted, const SkipRule& rule, double skip_share,
                                        const PredictionAttempts& tried, double now, const GoalDistance& distance,
                                        int count) {
  TargetList targets;
  const auto open = [&](const FrontierCluster& f) { return !tried.tried_lately(map, f.goal_x, f.goal_y, now); };
  for (const FrontierCluster* f : nearest_first(clusters, distance, open)) {
    if (static_cast<int>(targets.size()) >= count) break;
    // Checked after the cheap tests: under the region rule this is a flood fill.
    if (predicted.covered_share(map, *f, rule) >= skip_share) continue;
    targets.push_back({f->goal_x, f->goal_y});
  }
  return targets;
}

bool goal_serves_only_predicted(const std::vector<FrontierCluster>& clusters, double x, double y, double radius,
                                const std::function<bool(const FrontierCluster&)>& covered) {
  bool any = false;
  for (const FrontierCluster& f : clusters) {
    if (!f.has_goal || std::hypot(f.goal_x - x, f.goal_y - y) > radius) continue;
    if (!covered(f)) return false;
    any = true;
  }
  return any;
}

}  // namespace lookahead::exploration
