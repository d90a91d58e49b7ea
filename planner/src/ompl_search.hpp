// SPDX-License-Identifier: MIT
// The one door to OMPL: plan() hands it a costmap, two positions and the options and gets
// plain waypoints back. No OMPL type crosses this interface.
#pragma once

#include <cstddef>

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/path.hpp"
#include "lookahead/planner/planner_options.hpp"

namespace lookahead::planner::detail {

struct SearchOutcome {
  bool exact = false;      ///< OMPL reported EXACT_SOLUTION (approximate ones are dropped)
  Path raw;                ///< as the planner found it
  Path simplified;         ///< after PathSimplifier; empty when simplification is off
  std::size_t states = 0;  ///< vertices of the tree or roadmap
};

/// Plans in R^2 over the costmap's extent; start and goal must be free.
SearchOutcome search_with_ompl(const Costmap& costmap, Point2 start, Point2 goal, const PlannerOptions& options);

}  // namespace lookahead::planner::detail
