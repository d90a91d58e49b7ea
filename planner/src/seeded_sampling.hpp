// SPDX-License-Identifier: MIT
// The samplers of one plan() call, all seeded from PlannerOptions::seed (see "Determinism" in
// plan.hpp). OMPL would seed them from its process-wide seed sequence instead.
#pragma once

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/samplers/InformedStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

#include "informed_ellipse.hpp"
#include "lookahead/planner/path.hpp"

namespace lookahead::planner::detail {

/// Seeds and sample count shared by everything one plan() call allocates.
class SamplingContext {
 public:
  explicit SamplingContext(std::uint32_t seed) : seed_(seed) {}
  /// A new, distinct seed per call, deterministic in the order of the calls.
  std::uint32_t next_seed() { return derive(stream_.fetch_add(1)); }
  void count_sample() { samples_.fetch_add(1, std::memory_order_relaxed); }
  [[nodiscard]] std::int64_t samples() const { return samples_.load(std::memory_order_relaxed); }

  /// A path of length `cost` is known to exist: from now on the default sampler draws only
  /// from its informed ellipse (PlannerOptions::cost_bound).
  void bound_cost(const InformedEllipse& ellipse, double cost) {
    bound_ = ellipse;
    cost_bound_ = cost;
  }
  [[nodiscard]] const std::optional<InformedEllipse>& bound() const { return bound_; }
  [[nodiscard]] double cost_bound() const { return cost_bound_; }

 private:
  [[nodiscard]] std::uint32_t derive(std::uint64_t stream) const;

  std::uint32_t seed_;
  std::optional<InformedEllipse> bound_;
  double cost_bound_ = 0.0;
  std::atomic<std::uint64_t> stream_{0};
  std::atomic<std::int64_t> samples_{0};
};

/// R^2 whose default sampler is seeded from the context. Overriding allocDefaultStateSampler
/// (not just setStateSamplerAllocator) also catches samplers OMPL allocates internally.
class SeededPlane : public ompl::base::RealVectorStateSpace {
 public:
  explicit SeededPlane(std::shared_ptr<SamplingContext> context)
      : RealVectorStateSpace(2), context_(std::move(context)) {}
  ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;

 private:
  std::shared_ptr<SamplingContext> context_;
};

/// Path length whose informed sampler (Informed RRT*) is our seeded ellipse sampler: OMPL's
/// PathLengthDirectInfSampler keeps a private RNG nobody can seed.
class SeededPathLength : public ompl::base::PathLengthOptimizationObjective {
 public:
  SeededPathLength(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<SamplingContext> context, Point2 start,
                   Point2 goal, double goal_tolerance);
  ompl::base::InformedSamplerPtr allocInformedStateSampler(const ompl::base::ProblemDefinitionPtr& problem,
                                                           unsigned int max_calls) const override;

 private:
  std::shared_ptr<SamplingContext> context_;
  Point2 start_;
  Point2 goal_;
  double goal_tolerance_;
};

}  // namespace lookahead::planner::detail
