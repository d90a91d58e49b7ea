// SPDX-License-Identifier: MIT
#include "ompl_search.hpp"

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>

#include <algorithm>
#include <memory>

#include "costmap_checkers.hpp"
#include "seeded_planners.hpp"
#include "seeded_sampling.hpp"

namespace lookahead::planner::detail {
namespace ob = ompl::base;
namespace og = ompl::geometric;
namespace {

ob::SpaceInformationPtr make_space(const Costmap& costmap, const std::shared_ptr<SamplingContext>& context) {
  auto space = std::make_shared<SeededPlane>(context);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, costmap.min_corner().x);
  bounds.setLow(1, costmap.min_corner().y);
  bounds.setHigh(0, costmap.max_corner().x);
  bounds.setHigh(1, costmap.max_corner().y);
  space->setBounds(bounds);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker(std::make_shared<CostmapValidityChecker>(si, costmap));
  si->setMotionValidator(std::make_shared<CostmapMotionValidator>(si, costmap));
  // The motion check above is exact, but OMPL also interpolates with this step (path
  // subdivision, getMotionStates); its default of 1 % of the extent is metres on a building.
  si->setStateValidityCheckingResolution(0.5 * costmap.resolution() / space->getMaximumExtent());
  si->setup();
  return si;
}

ob::PlannerPtr make_planner(const ob::SpaceInformationPtr& si, const PlannerOptions& options,
                            SamplingContext& context) {
  const std::uint32_t seed = context.next_seed();
  switch (options.algorithm) {
    case PlannerAlgorithm::kPrmStar:
      return std::make_shared<SequentialPrmStar>(si, seed);
    case PlannerAlgorithm::kInformedRrtStar: {
      auto planner = std::make_shared<SeededInformedRrtStar>(si, seed);
      planner->setGoalBias(options.goal_bias);
      if (options.range > 0.0) planner->setRange(options.range);
      return planner;
    }
    case PlannerAlgorithm::kRrtStar:
      break;
  }
  auto planner = std::make_shared<SeededRrtStar>(si, seed);
  planner->setGoalBias(options.goal_bias);
  if (options.range > 0.0) planner->setRange(options.range);
  return planner;
}

std::size_t count_states(const ob::PlannerPtr& planner, const ob::SpaceInformationPtr& si) {
  // PRM's planner data lists only vertices with edges; its milestone count is exact.
  if (const auto* prm = dynamic_cast<const og::PRM*>(planner.get())) return prm->milestoneCount();
  ob::PlannerData data(si);
  planner->getPlannerData(data);
  return data.numVertices();
}

Path to_path(const og::PathGeometric& path) {
  Path out;
  out.reserve(path.getStateCount());
  for (std::size_t i = 0; i < path.getStateCount(); ++i) {
    const double* v = path.getState(static_cast<unsigned int>(i))->as<ob::RealVectorStateSpace::StateType>()->values;
    out.push_back({v[0], v[1]});
  }
  return out;
}

/// Shortcut and smooth with a fixed number of steps (no wall clock, so it stays repeatable).
Path simplify(const og::PathGeometric& found, const ob::SpaceInformationPtr& si, SamplingContext& context) {
  og::PathGeometric path(found);
  SeededPathSimplifier simplifier(si, context.next_seed());
  simplifier.reduceVertices(path);
  simplifier.shortcutPath(path);
  simplifier.reduceVertices(path);
  // Three B-spline rounds round the corners the shortcuts leave; each round keeps only the
  // moves whose new segments pass the (exact) motion check.
  simplifier.smoothBSpline(path, 3, path.length() / 100.0);
  return to_path(path);
}

/// The sample budget of a search whose ellipse has `area` [m^2] (samples_per_m2).
std::int64_t bounded_samples(const PlannerOptions& options, double area) {
  if (options.samples_per_m2 <= 0.0) return options.max_samples;
  auto n = static_cast<std::int64_t>(std::ceil(options.samples_per_m2 * area));
  n = std::max(n, kMinBoundedSamples);
  return options.max_samples > 0 ? std::min(n, options.max_samples) : n;
}

/// A sample budget alone ends a sample-limited search: a clock would cut it at a point that
/// depends on the machine's load, and the same seed would give different paths. Only a
/// search without one (max_samples = 0) is ended by time_budget.
ob::PlannerTerminationCondition termination(const PlannerOptions& options,
                                            const std::shared_ptr<SamplingContext>& context, std::int64_t max_samples) {
  if (max_samples <= 0) return ob::timedPlannerTerminationCondition(options.time_budget);
  return ob::PlannerTerminationCondition([context, max_samples] { return context->samples() >= max_samples; });
}

}  // namespace

SearchOutcome search_with_ompl(const Costmap& costmap, Point2 start, Point2 goal, const PlannerOptions& options) {
  auto context = std::make_shared<SamplingContext>(options.seed);
  std::int64_t max_samples = options.max_samples;
  if (options.cost_bound > 0.0) {
    const InformedEllipse ellipse(start, goal, options.goal_tolerance);
    context->bound_cost(ellipse, options.cost_bound);
    max_samples = bounded_samples(options, ellipse.area(options.cost_bound));
  }
  const ob::SpaceInformationPtr si = make_space(costmap, context);
  auto problem = std::make_shared<ob::ProblemDefinition>(si);
  ob::ScopedState<ob::RealVectorStateSpace> s(si->getStateSpace());
  ob::ScopedState<ob::RealVectorStateSpace> g(si->getStateSpace());
  s->values[0] = start.x;
  s->values[1] = start.y;
  g->values[0] = goal.x;
  g->values[1] = goal.y;
  // OMPL's goal test is strict (distance < threshold): a tolerance of 0 would never be met.
  problem->setStartAndGoalStates(s, g, std::max(options.goal_tolerance, 1e-9));
  problem->setOptimizationObjective(
      std::make_shared<SeededPathLength>(si, context, start, goal, options.goal_tolerance));

  const ob::PlannerPtr planner = make_planner(si, options, *context);
  planner->setProblemDefinition(problem);
  planner->setup();
  const ob::PlannerStatus status = planner->solve(termination(options, context, max_samples));

  SearchOutcome outcome;
  outcome.states = count_states(planner, si);
  // PlannerStatus converts to true for APPROXIMATE_SOLUTION too: only EXACT is a path.
  outcome.exact = status == ob::PlannerStatus::EXACT_SOLUTION && problem->hasExactSolution();
  if (!outcome.exact) return outcome;
  const auto* found = problem->getSolutionPath()->as<og::PathGeometric>();
  outcome.raw = to_path(*found);
  if (options.simplify) outcome.simplified = simplify(*found, si, *context);
  return outcome;
}

}  // namespace lookahead::planner::detail
