// SPDX-License-Identifier: MIT
#include "seeded_planners.hpp"

#include <ompl/base/goals/GoalSampleableRegion.h>

namespace lookahead::planner::detail {
namespace ob = ompl::base;

ob::PlannerStatus SequentialPrmStar::solve(const ob::PlannerTerminationCondition& ptc) {
  checkValidity();
  auto* goal = dynamic_cast<ob::GoalSampleableRegion*>(pdef_->getGoal().get());
  if (goal == nullptr) return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
  while (const ob::State* start = pis_.nextStart()) {
    startM_.push_back(addMilestone(si_->cloneState(start)));
  }
  if (startM_.empty()) return ob::PlannerStatus::INVALID_START;
  if (goalM_.empty()) {
    if (const ob::State* g = pis_.nextGoal(ptc)) goalM_.push_back(addMilestone(si_->cloneState(g)));
  }
  if (goalM_.empty()) return ob::PlannerStatus::INVALID_GOAL;

  growRoadmap(ptc);  // the whole budget: PRM* keeps improving the roadmap, like RRT*

  for (const Vertex s : startM_) {
    for (const Vertex g : goalM_) {
      if (!sameComponent(s, g)) continue;
      const ob::PathPtr path = constructSolution(s, g);
      if (!path) continue;
      pdef_->addSolutionPath(path, false, 0.0, getName());
      return ob::PlannerStatus::EXACT_SOLUTION;
    }
  }
  return ob::PlannerStatus::TIMEOUT;
}

}  // namespace lookahead::planner::detail
