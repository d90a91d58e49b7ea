// SPDX-License-Identifier: MIT
// OMPL's planners and path simplifier with their own RNGs reseeded from the plan() seed.
// The RNG members are protected in OMPL 1.5, so a constructor can call setLocalSeed on them;
// nothing else about the algorithms changes, except PRM*'s driver (below).
#pragma once

#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <cstdint>

namespace lookahead::planner::detail {

class SeededRrtStar : public ompl::geometric::RRTstar {
 public:
  SeededRrtStar(const ompl::base::SpaceInformationPtr& si, std::uint32_t seed) : RRTstar(si) {
    rng_.setLocalSeed(seed);
  }
};

class SeededInformedRrtStar : public ompl::geometric::InformedRRTstar {
 public:
  SeededInformedRrtStar(const ompl::base::SpaceInformationPtr& si, std::uint32_t seed) : InformedRRTstar(si) {
    rng_.setLocalSeed(seed);
  }
};

/// PRM* (Karaman & Frazzoli 2011, Alg. 4): sample a valid state, connect it to its k-nearest
/// neighbours (k = e (1 + 1/d) log n), repeat until the termination condition, then A* over
/// the roadmap. Deviation from OMPL's PRM::solve, which interleaves this with PRM's random
/// "expansion" walks on a wall-clock schedule and looks for solutions on a second thread: both
/// make its output depend on timing. The paper's PRM* has no expansion step.
class SequentialPrmStar : public ompl::geometric::PRMstar {
 public:
  SequentialPrmStar(const ompl::base::SpaceInformationPtr& si, std::uint32_t seed) : PRMstar(si) {
    rng_.setLocalSeed(seed);
  }
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
};

class SeededPathSimplifier : public ompl::geometric::PathSimplifier {
 public:
  SeededPathSimplifier(const ompl::base::SpaceInformationPtr& si, std::uint32_t seed) : PathSimplifier(si) {
    rng_.setLocalSeed(seed);
  }
};

}  // namespace lookahead::planner::detail
