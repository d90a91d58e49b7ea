// SPDX-License-Identifier: MIT
#include "lookahead/exploration/prediction_targets.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {

namespace {

// The clusters' goals passing `keep`, nearest to the robot first.
template <typename Keep>
std::vector<const FrontierCluster*> nearest_first(const std::vector<FrontierCluster>& clusters,
                                                  const slam::Pose2& robot, const Keep& keep) {
  std::vector<std::pair<double, const FrontierCluster*>> goals;
  for (const FrontierCluster& f : clusters)
    if (f.has_goal && keep(f)) goals.push_back({std::hypot(f.goal_x - robot.x, f.goal_y - robot.y), &f});
  std::sort(goals.begin(), goals.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const FrontierCluster*> out;
  for (const auto& g : goals) out.push_back(g.second);
  return out;
}

}  // namespace

TargetList selection_targets(const std::vector<FrontierCluster>& clusters, double goal_x, double goal_y,
                             const slam::Pose2& robot, int count) {
  TargetList targets{{goal_x, goal_y}};
  const auto other = [&](const FrontierCluster& f) { return std::hypot(f.goal_x - goal_x, f.goal_y - goal_y) >= 1.0; };
  for (const FrontierCluster* f : nearest_first(clusters, robot, other)) {
    if (static_cast<int>(targets.size()) >= count) break;
    targets.push_back({f->goal_x, f->goal_y});
  }
  return targets;
}

TargetList unpredicted_frontier_targets(const std::vector<FrontierCluster>& clusters, const slam::OccupancyGrid& map,
                                        const PredictedMap& predicted, const SkipRule& rule, double skip_share,
                                        const GoalBlacklist& tried, double now, const slam::Pose2& robot, int count) {
  TargetList targets;
  const auto open = [&](const FrontierCluster& f) { return !tried.contains(f.goal_x, f.goal_y, now); };
  for (const FrontierCluster* f : nearest_first(clusters, robot, open)) {
    if (static_cast<int>(targets.size()) >= count) break;
    // Checked after the cheap tests: under the region rule this is a flood fill.
    if (predicted.covered_share(map, *f, rule) >= skip_share) continue;
    targets.push_back({f->goal_x, f->goal_y});
  }
  return targets;
}

}  // namespace lookahead::exploration
