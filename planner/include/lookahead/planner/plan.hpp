// SPDX-License-Identifier: MIT
// plan(map, pose, target): a collision-free path for a disc robot on an occupancy grid.
//
// Steps, in order:
//  1. Costmap: obstacles (and, by default, unknown cells) inflated by the robot radius, so the
//     robot is a point (costmap.hpp).
//  2. Pre-checks that need no search: finite input, start free, goal free, and a 4-connected
//     flood fill of the free cells; a goal outside the start's component is reported as
//     no_path at once instead of after the whole budget.
//     A goal in free line of sight is answered with the straight segment, the shortest
//     path there is (what every asymptotically optimal planner converges to).
//  3. OMPL geometric planning in R^2 (position only): the robot is a disc, so after inflation
//     its heading never decides a collision, and SE(2) would only add a dimension to sample.
//     The follower turns the robot on the spot where the path bends (path_follower.hpp).
//     Motions are checked with the costmap's exact cell walk; OMPL's discretisation step is
//     also set to half a cell (its default, 1 % of the extent, would skip 5 cm cells).
//     Only an EXACT solution counts: OMPL's PlannerStatus is also "true" when approximate.
//     With PlannerOptions::cost_bound (a path length known from a grid search) every sample
//     is drawn from the informed ellipse of that cost (Informed RRT*'s set, from the start).
//  4. Simplification (OMPL PathSimplifier: vertex reduction, shortcuts, B-spline smoothing).
//  5. Guard: the returned path is re-checked segment by segment at cell resolution. A path
//     that fails is never returned as solved: the raw path is tried instead, and if that fails
//     too the result is no_path; every failure is counted in guard_rejections.
//
// Determinism. OMPL 1.5's ompl::RNG::setSeed() is process-wide and takes effect only before
// the first RNG exists, so it cannot make two plan() calls in one process repeat. Instead
// every RNG that decides the output is reseeded locally from PlannerOptions::seed: the state
// samplers, the planner's own RNG (goal bias), the informed sampler and the path simplifier.
// PRM* runs single-threaded here (OMPL's PRM::solve checks for solutions on a second thread
// and alternates its steps by wall-clock time). The one RNG left unseeded picks the pivots of
// OMPL's nearest-neighbour tree (GNAT, seeded from the process-wide sequence); its search is
// exact, so that can only reorder equally distant neighbours, which continuous random
// samples make vanishingly unlikely. Checked: same paths across processes and call orders.
// Result: with the same seed and a sample budget (max_samples, samples_per_m2), the path is
// the same in any process, call order and machine load: no clock takes part in that search.
// Only a search without a sample budget is ended by time_budget, and depends on the speed.
#pragma once

#include <cstddef>
#include <string>

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path.hpp"
#include "lookahead/planner/planner_options.hpp"
#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::planner {

enum class PlanStatus {
  kSolved,        ///< path holds a checked, collision-free path from start to goal
  kStartBlocked,  ///< the start lies in an obstacle, its inflation, unknown space or off-map
  kGoalBlocked,   ///< the same for the goal
  kNoPath,        ///< unreachable, or no exact solution within the budget
  kInvalidInput,  ///< non-finite coordinates or an empty map (options throw instead)
};

[[nodiscard]] const char* to_string(PlanStatus status);

struct PlanResult {
  PlanStatus status = PlanStatus::kInvalidInput;
  PlannerAlgorithm algorithm = PlannerAlgorithm::kRrtStar;
  Path path;                         ///< start first; empty unless solved
  double length = 0.0;               ///< of `path` [m]
  double planning_time = 0.0;        ///< whole plan() call, wall clock [s]
  std::size_t states = 0;            ///< vertices of the tree or roadmap
  std::size_t guard_rejections = 0;  ///< paths the final check refused (should stay 0)
  std::string message;               ///< why, for logs and reports

  [[nodiscard]] bool solved() const { return status == PlanStatus::kSolved; }
};

/// Builds the costmap from `map` (options.costmap) and plans from the start pose's position
/// to (goal_x, goal_y). Throws std::invalid_argument for invalid options only.
[[nodiscard]] PlanResult plan(const slam::OccupancyGrid& map, const slam::Pose2& start, double goal_x, double goal_y,
                              const PlannerOptions& options);

/// Same on a costmap the caller already built (replanning on an unchanged map);
/// options.costmap is ignored.
[[nodiscard]] PlanResult plan(const Costmap& costmap, const slam::Pose2& start, double goal_x, double goal_y,
                              const PlannerOptions& options);

}  // namespace lookahead::planner
