// SPDX-License-Identifier: MIT
#include "seeded_sampling.hpp"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cmath>

namespace lookahead::planner::detail {
namespace ob = ompl::base;

std::uint32_t SamplingContext::derive(std::uint64_t stream) const {
  // splitmix64 finaliser: neighbouring (seed, stream) pairs give unrelated seeds.
  std::uint64_t z = (static_cast<std::uint64_t>(seed_) << 32 | stream) + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return static_cast<std::uint32_t>(z ^ (z >> 31));
}

namespace {

/// Uniform sampler over the bounds, or over the informed ellipse when the context knows a
/// cost bound, whose RNG (protected in ompl::base::StateSampler) is reseeded locally, and
/// which counts its draws for PlannerOptions::max_samples.
class SeededSampler : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::shared_ptr<SamplingContext> context)
      : RealVectorStateSampler(space), context_(std::move(context)) {
    rng_.setLocalSeed(context_->next_seed());
  }
  void sampleUniform(ob::State* state) override {
    context_->count_sample();
    if (context_->bound() && sample_bounded(state)) return;
    RealVectorStateSampler::sampleUniform(state);
  }

 private:
  // An ellipse reaching far past the map is rejected and redrawn a few times; an ellipse
  // mostly off the map cannot happen for a bound from a path on the map.
  bool sample_bounded(ob::State* state) {
    for (int attempt = 0; attempt < 16; ++attempt) {
      const Point2 p = context_->bound()->sample(context_->cost_bound(), rng_);
      double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
      v[0] = p.x;
      v[1] = p.y;
      if (space_->satisfiesBounds(state)) return true;
    }
    return false;
  }

  std::shared_ptr<SamplingContext> context_;
};

/// Informed RRT*'s sampler: the ellipse of the best solution's cost (InformedEllipse).
class EllipseInformedSampler : public ob::InformedSampler {
 public:
  EllipseInformedSampler(const ob::ProblemDefinitionPtr& problem, unsigned int max_calls,
                         const std::shared_ptr<SamplingContext>& context, Point2 start, Point2 goal, double tolerance)
      : InformedSampler(problem, max_calls),
        context_(context),
        uniform_(space_->allocDefaultStateSampler()),
        rng_(context->next_seed()),
        ellipse_(start, goal, tolerance) {}

  bool sampleUniform(ob::State* state, const ob::Cost& max_cost) override {
    if (!opt_->isFinite(max_cost)) {  // no solution yet: the whole space (or the known bound)
      uniform_->sampleUniform(state);
      return true;
    }
    context_->count_sample();  // one draw for max_samples, however many rejections it takes
    for (unsigned int i = 0; i < numIters_; ++i) {
      const Point2 p = ellipse_.sample(max_cost.value(), rng_);
      double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
      v[0] = p.x;
      v[1] = p.y;
      if (space_->satisfiesBounds(state)) return true;
    }
    return false;
  }

  bool sampleUniform(ob::State* state, const ob::Cost& min_cost, const ob::Cost& max_cost) override {
    for (unsigned int i = 0; i < numIters_; ++i) {
      if (!sampleUniform(state, max_cost)) return false;
      if (!opt_->isCostBetterThan(heuristicSolnCost(state), min_cost)) return true;
    }
    return false;
  }

  bool hasInformedMeasure() const override { return true; }

  double getInformedMeasure(const ob::Cost& current) const override {
    if (!opt_->isFinite(current)) return space_->getMeasure();
    return std::min(space_->getMeasure(), ellipse_.area(current.value()));
  }

 private:
  std::shared_ptr<SamplingContext> context_;
  ob::StateSamplerPtr uniform_;  // counts its own draws
  ompl::RNG rng_;
  InformedEllipse ellipse_;
};

}  // namespace

ob::StateSamplerPtr SeededPlane::allocDefaultStateSampler() const {
  return std::make_shared<SeededSampler>(this, context_);
}

SeededPathLength::SeededPathLength(const ob::SpaceInformationPtr& si, std::shared_ptr<SamplingContext> context,
                                   Point2 start, Point2 goal, double goal_tolerance)
    : PathLengthOptimizationObjective(si),
      context_(std::move(context)),
      start_(start),
      goal_(goal),
      goal_tolerance_(goal_tolerance) {}

ob::InformedSamplerPtr SeededPathLength::allocInformedStateSampler(const ob::ProblemDefinitionPtr& problem,
                                                                   unsigned int max_calls) const {
  return std::make_shared<EllipseInformedSampler>(problem, max_calls, context_, start_, goal_, goal_tolerance_);
}

}  // namespace lookahead::planner::detail
