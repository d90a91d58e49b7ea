// SPDX-License-Identifier: MIT
// The costmap seen through OMPL's two collision interfaces. The motion validator walks the
// cells exactly (segment_walk.hpp) instead of OMPL's DiscreteMotionValidator, which tests
// points a fixed step apart and can clip the corner of a cell between two of them.
#pragma once

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include "lookahead/planner/costmap.hpp"

namespace lookahead::planner::detail {

class CostmapValidityChecker : public ompl::base::StateValidityChecker {
 public:
  CostmapValidityChecker(const ompl::base::SpaceInformationPtr& si, const Costmap& costmap)
      : StateValidityChecker(si), costmap_(costmap) {}
  bool isValid(const ompl::base::State* state) const override;

 private:
  const Costmap& costmap_;  // outlives the OMPL objects of one plan() call
};

class CostmapMotionValidator : public ompl::base::MotionValidator {
 public:
  CostmapMotionValidator(const ompl::base::SpaceInformationPtr& si, const Costmap& costmap)
      : MotionValidator(si), costmap_(costmap) {}
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// Also reports the last free state before the first blocked cell, and its fraction of
  /// the motion.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& last_valid) const override;

 private:
  const Costmap& costmap_;
};

}  // namespace lookahead::planner::detail
