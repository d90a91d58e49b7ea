// SPDX-License-Identifier: MIT
// plan(): the steps listed in plan.hpp, one named call each.
#include "lookahead/planner/plan.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <optional>

#include "ompl_search.hpp"
#include "reachability.hpp"

namespace lookahead::planner {
namespace {

PlanResult failure(PlanStatus status, std::string message) {
  PlanResult r;
  r.status = status;
  r.message = std::move(message);
  return r;
}

/// Step 2: the answers that need no search.
std::optional<PlanResult> precheck(const Costmap& costmap, Point2 start, Point2 goal, const PlannerOptions& options) {
  if (!std::isfinite(start.x) || !std::isfinite(start.y) || !std::isfinite(goal.x) || !std::isfinite(goal.y)) {
    return failure(PlanStatus::kInvalidInput, "start or goal is not finite");
  }
  if (costmap.empty()) return failure(PlanStatus::kInvalidInput, "the map has no known cells");
  if (!costmap.is_free(start)) {
    return failure(PlanStatus::kStartBlocked, "start is in an obstacle, its inflation, unknown space or off the map");
  }
  if (!costmap.is_free(goal)) {
    return failure(PlanStatus::kGoalBlocked, "goal is in an obstacle, its inflation, unknown space or off the map");
  }
  if (!detail::reachable(costmap, start, goal, options.goal_tolerance)) {
    return failure(PlanStatus::kNoPath, "goal unreachable: not connected to the start");
  }
  return std::nullopt;
}

/// Ends the path at the exact goal when it stopped within the tolerance short of it.
void end_at_goal(Path& path, Point2 goal, const Costmap& costmap) {
  if (!path.empty() && path.back() != goal && costmap.segment_is_free(path.back(), goal)) {
    path.push_back(goal);
  }
}

/// Step 5: the first candidate that passes the independent re-check; failures are counted.
std::optional<Path> guard(const Costmap& costmap, std::initializer_list<const Path*> candidates,
                          std::size_t& rejections) {
  for (const Path* path : candidates) {
    if (path->empty()) continue;
    if (costmap.path_is_free(*path)) return *path;
    ++rejections;
    spdlog::warn("planner: a {}-waypoint path failed the final collision check; not used", path->size());
  }
  return std::nullopt;
}

PlanResult search(const Costmap& costmap, Point2 start, Point2 goal, const PlannerOptions& options) {
  if (costmap.segment_is_free(start, goal)) {
    // The straight segment is the shortest path there is: every optimal planner converges
    // to it, so no samples are spent on finding it again.
    PlanResult r;
    r.status = PlanStatus::kSolved;
    r.path = start == goal ? Path{start} : Path{start, goal};
    r.message = distance(start, goal) <= options.goal_tolerance ? "already at the goal" : "straight segment";
    return r;
  }
  detail::SearchOutcome found = detail::search_with_ompl(costmap, start, goal, options);
  PlanResult r;
  r.states = found.states;
  if (!found.exact) {
    r.status = PlanStatus::kNoPath;
    r.message = "no exact solution within the budget";
    return r;
  }
  end_at_goal(found.raw, goal, costmap);
  end_at_goal(found.simplified, goal, costmap);
  std::optional<Path> checked = guard(costmap, {&found.simplified, &found.raw}, r.guard_rejections);
  if (!checked) {
    r.status = PlanStatus::kNoPath;
    r.message = "every path found failed the final collision check";
    return r;
  }
  r.status = PlanStatus::kSolved;
  r.path = std::move(*checked);
  r.message = r.guard_rejections ? "simplified path rejected; raw path returned" : "solved";
  return r;
}

}  // namespace

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSolved:
      return "solved";
    case PlanStatus::kStartBlocked:
      return "start_blocked";
    case PlanStatus::kGoalBlocked:
      return "goal_blocked";
    case PlanStatus::kNoPath:
      return "no_path";
    case PlanStatus::kInvalidInput:
      return "invalid_input";
  }
  return "unknown";
}

PlanResult plan(const Costmap& costmap, const slam::Pose2& start, double goal_x, double goal_y,
                const PlannerOptions& options) {
  validate(options);
  const auto t0 = std::chrono::steady_clock::now();
  const Point2 s{start.x, start.y};
  const Point2 g{goal_x, goal_y};
  const std::optional<PlanResult> verdict = precheck(costmap, s, g, options);
  PlanResult r = verdict ? *verdict : search(costmap, s, g, options);
  r.algorithm = options.algorithm;
  r.length = path_length(r.path);
  r.planning_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  spdlog::debug("planner: {} {} in {:.3f} s, {} states, {:.2f} m: {}", to_string(r.algorithm), to_string(r.status),
                r.planning_time, r.states, r.length, r.message);
  return r;
}

PlanResult plan(const slam::OccupancyGrid& map, const slam::Pose2& start, double goal_x, double goal_y,
                const PlannerOptions& options) {
  validate(options);
  const auto t0 = std::chrono::steady_clock::now();
  const Costmap costmap(map, options.costmap);
  PlanResult r = plan(costmap, start, goal_x, goal_y, options);
  r.planning_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace lookahead::planner
