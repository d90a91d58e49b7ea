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

/// Uniform sampler over the bounds whose RNG (protected in ompl::base::StateSampler) is
/// reseeded locally, and which counts its draws for PlannerOptions::max_samples.
class SeededSampler : public ob::RealVectorStateSampler {
 public:
  SeededSampler(const ob::StateSpace* space, std::shared_ptr<SamplingContext> context)
      : RealVectorStateSampler(space), context_(std::move(context)) {
    rng_.setLocalSeed(context_->next_seed());
  }
  void sampleUniform(ob::State* state) override {
    context_->count_sample();
    RealVectorStateSampler::sampleUniform(state);
  }

 private:
  std::shared_ptr<SamplingContext> context_;
};

/// Direct sampling of the informed set in R^2: Gammell et al. (IROS 2014), Sec. IV. For path
/// length with start s and goal g, a state x can lie on a path of cost < c only if
/// |x - s| + |x - g| <= c + goal_tolerance (the path may stop that short of g), an ellipse.
/// Deviation: the tolerance widens the ellipse; the paper has a point goal.
class EllipseInformedSampler : public ob::InformedSampler {
 public:
  EllipseInformedSampler(const ob::ProblemDefinitionPtr& problem, unsigned int max_calls,
                         const std::shared_ptr<SamplingContext>& context, Point2 start, Point2 goal,
                         double tolerance)
      : InformedSampler(problem, max_calls),
        context_(context),
        uniform_(space_->allocDefaultStateSampler()),
        rng_(context->next_seed()),
        centre_{0.5 * (start.x + goal.x), 0.5 * (start.y + goal.y)},
        half_focal_(0.5 * distance(start, goal)),
        angle_(std::atan2(goal.y - start.y, goal.x - start.x)),
        tolerance_(tolerance) {}

  bool sampleUniform(ob::State* state, const ob::Cost& max_cost) override {
    if (!opt_->isFinite(max_cost)) {  // no solution yet: the whole space is informative
      uniform_->sampleUniform(state);
      return true;
    }
    context_->count_sample();  // one draw for max_samples, however many rejections it takes
    for (unsigned int i = 0; i < numIters_; ++i) {
      sample_ellipse(max_cost.value(), state);
      if (space_->satisfiesBounds(state)) return true;
    }
    return false;
  }

  bool sampleUniform(ob::State* state, const ob::Cost& min_cost,
                     const ob::Cost& max_cost) override {
    for (unsigned int i = 0; i < numIters_; ++i) {
      if (!sampleUniform(state, max_cost)) return false;
      if (!opt_->isCostBetterThan(heuristicSolnCost(state), min_cost)) return true;
    }
    return false;
  }

  bool hasInformedMeasure() const override { return true; }

  double getInformedMeasure(const ob::Cost& current) const override {
    if (!opt_->isFinite(current)) return space_->getMeasure();
    const double a = semi_major(current.value());
    return std::min(space_->getMeasure(), M_PI * a * semi_minor(a));
  }

 private:
  double semi_major(double cost) const { return std::max(0.5 * (cost + tolerance_), half_focal_); }
  double semi_minor(double a) const {
    return std::sqrt(std::max(a * a - half_focal_ * half_focal_, 0.0));
  }

  void sample_ellipse(double cost, ob::State* state) {
    const double a = semi_major(cost);
    const double b = semi_minor(a);
    // Uniform in the unit disc (sqrt for the radius), stretched to the ellipse, rotated.
    const double r = std::sqrt(rng_.uniform01());
    const double phi = rng_.uniformReal(-M_PI, M_PI);
    const double ex = a * r * std::cos(phi);
    const double ey = b * r * std::sin(phi);
    double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    v[0] = centre_.x + ex * std::cos(angle_) - ey * std::sin(angle_);
    v[1] = centre_.y + ex * std::sin(angle_) + ey * std::cos(angle_);
  }

  std::shared_ptr<SamplingContext> context_;
  ob::StateSamplerPtr uniform_;  // counts its own draws
  ompl::RNG rng_;
  Point2 centre_;
  double half_focal_;
  double angle_;
  double tolerance_;
};

}  // namespace

ob::StateSamplerPtr SeededPlane::allocDefaultStateSampler() const {
  return std::make_shared<SeededSampler>(this, context_);
}

SeededPathLength::SeededPathLength(const ob::SpaceInformationPtr& si,
                                   std::shared_ptr<SamplingContext> context, Point2 start,
                                   Point2 goal, double goal_tolerance)
    : PathLengthOptimizationObjective(si),
      context_(std::move(context)),
      start_(start),
      goal_(goal),
      goal_tolerance_(goal_tolerance) {}

ob::InformedSamplerPtr SeededPathLength::allocInformedStateSampler(
    const ob::ProblemDefinitionPtr& problem, unsigned int max_calls) const {
  return std::make_shared<EllipseInformedSampler>(problem, max_calls, context_, start_, goal_,
                                                  goal_tolerance_);
}

}  // namespace lookahead::planner::detail
