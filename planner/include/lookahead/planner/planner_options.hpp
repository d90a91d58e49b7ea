// SPDX-License-Identifier: MIT
// Every parameter of plan(), with the costmap's nested. The defaults here are the only copy.
#pragma once

#include <array>
#include <cstdint>
#include <utility>

#include "lookahead/planner/costmap.hpp"

namespace lookahead::planner {

/// The sampling-based planners plan() offers, all asymptotically optimal for path length.
enum class PlannerAlgorithm {
  /// RRT*: Karaman & Frazzoli, "Sampling-based algorithms for optimal motion planning",
  /// IJRR 30(7), 2011, Alg. 6 (OMPL's k-nearest variant).
  kRrtStar,
  /// PRM*: same paper, Alg. 4 (k-nearest connections, no expansion step).
  kPrmStar,
  /// Informed RRT*: Gammell, Srinivasa & Barfoot, IROS 2014: RRT* that, once a path of length
  /// c exists, samples only the ellipse of points that could shorten it.
  kInformedRrtStar,
};

/// The algorithms' names (planner.algorithm in YAML; a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<PlannerAlgorithm, const char*>, 3> choice_names(PlannerAlgorithm) {
  return {{{PlannerAlgorithm::kRrtStar, "rrt_star"},
           {PlannerAlgorithm::kPrmStar, "prm_star"},
           {PlannerAlgorithm::kInformedRrtStar, "informed_rrt_star"}}};
}

[[nodiscard]] const char* to_string(PlannerAlgorithm algorithm);

/// Fewest samples a search bounded by samples_per_m2 gets: enough for RRT* to bend round a
/// corner or through a door inside even a thin ellipse.
inline constexpr std::int64_t kMinBoundedSamples = 300;

struct PlannerOptions {
  PlannerAlgorithm algorithm = PlannerAlgorithm::kRrtStar;
  /// Wall-clock budget of a search without a sample budget [s], (0, 60]. The planners are
  /// anytime: they keep shortening the path until the budget is spent. Costmap construction
  /// and path simplification come on top (linear-time passes, milliseconds). Ignored when
  /// the search has a sample budget (max_samples or samples_per_m2).
  double time_budget = 0.5;
  /// Stop after this many samples, 0 = no limit (time_budget ends the search), [0, 1e8].
  /// A search with a sample budget is ended by that count alone, never by the clock, so
  /// its result depends on `seed` only, whatever the load (see determinism in plan.hpp).
  std::int64_t max_samples = 0;
  /// A path may end this close to the goal [m], [0, 5]; the exact goal is appended when the
  /// last segment to it is free.
  double goal_tolerance = 0.1;
  /// Longest tree edge of RRT* / Informed RRT* [m], [0, 1000]; 0 = OMPL's default (20 % of
  /// the costmap's diagonal).
  double range = 0.0;
  /// Probability of steering RRT* / Informed RRT* towards the goal, [0, 1].
  double goal_bias = 0.05;
  /// Shortcut and B-spline smoothing (OMPL PathSimplifier) of the found path.
  bool simplify = true;
  /// Length of a path from start to goal known to exist [m] (e.g. one a grid search found),
  /// [0, 1e6]; 0 = none known. Every sampler then draws from the informed ellipse of that
  /// cost from the first sample on (Gammell et al., IROS 2014, with c_best given instead of
  /// found): no shorter path leaves it, so the samples go where they can help.
  double cost_bound = 0.0;
  /// With a cost_bound: samples per m^2 of its ellipse, [0, 1e6]; the search then stops
  /// after that many samples (at least kMinBoundedSamples, at most max_samples), so a short
  /// hop costs few samples and a long detour many. 0 = max_samples alone.
  double samples_per_m2 = 0.0;
  /// Seed of every random draw of one plan() call, [0, 2^32).
  std::uint32_t seed = 1;
  CostmapOptions costmap;
};

/// Throws std::invalid_argument naming the field and value when an option is out of range
/// (the nested costmap options included).
void validate(const PlannerOptions& options);

}  // namespace lookahead::planner
