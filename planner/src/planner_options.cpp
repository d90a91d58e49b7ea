// SPDX-License-Identifier: MIT
#include "lookahead/planner/planner_options.hpp"

#include "option_check.hpp"

namespace lookahead::planner {

const char* to_string(PlannerAlgorithm algorithm) {
  for (const auto& [a, name] : choice_names(algorithm)) {
    if (a == algorithm) return name;
  }
  return "unknown";
}

void validate(const PlannerOptions& o) {
  using detail::Bound;
  using detail::check_range;
  switch (o.algorithm) {
    case PlannerAlgorithm::kRrtStar:
    case PlannerAlgorithm::kPrmStar:
    case PlannerAlgorithm::kInformedRrtStar:
      break;
    default:
      throw std::invalid_argument("PlannerOptions.algorithm = " + std::to_string(static_cast<int>(o.algorithm)) +
                                  " is not a PlannerAlgorithm");
  }
  check_range("PlannerOptions.time_budget", o.time_budget, 0.0, 60.0, "s", Bound::kOpen);
  check_range("PlannerOptions.max_samples", static_cast<double>(o.max_samples), 0.0, 1e8, "");
  check_range("PlannerOptions.goal_tolerance", o.goal_tolerance, 0.0, 5.0, "m");
  check_range("PlannerOptions.range", o.range, 0.0, 1000.0, "m");
  check_range("PlannerOptions.goal_bias", o.goal_bias, 0.0, 1.0, "");
  check_range("PlannerOptions.cost_bound", o.cost_bound, 0.0, 1e6, "m");
  check_range("PlannerOptions.samples_per_m2", o.samples_per_m2, 0.0, 1e6, "1/m^2");
  validate(o.costmap);
}

}  // namespace lookahead::planner
