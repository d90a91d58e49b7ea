// SPDX-License-Identifier: MIT
// The coarse search that seeds matching's ICP (SegSLAM sec. 4.5; the deviation is stated in
// grid_submap_ops.cpp): on a grid of poses around a guess, the pose that puts the most
// window points near a candidate's obstacles (NearField level 0). Two searches that return
// the same pose: the exhaustive one, and a branch and bound over blocks of 2^h x 2^h
// translations whose bound reads the dilated NearField levels.
#pragma once

#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/segslam/binned_icp.hpp"
#include "lookahead/slam/segslam/near_field.hpp"

namespace lookahead::slam::segslam {

/// Poses centre + (i step, j step, a angle_step) for |i|, |j| <= radius / step and
/// |a| <= angle / angle_step.
struct PoseGrid {
  double radius = 2.0, step = 0.25;        ///< [m]
  double angle = 0.25, angle_step = 0.05;  ///< [rad]
};

struct CoarseResult {
  Pose2 pose;
  int score = -1;  ///< points near an obstacle at `pose`
};

/// The NearField dilations (one per level above 0) the branch and bound needs for `grid` on
/// a map of `resolution`.
std::vector<int> branch_and_bound_dilations(const PoseGrid& grid, double resolution);

/// Every pose of the grid; ties go to the first in (angle, x, y) order.
CoarseResult coarse_search_exhaustive(const NearField& field, const Points2& points, const Pose2& centre,
                                      const PoseGrid& grid);

/// The same optimum (same tie-breaking) by branch and bound; `field` must hold the levels of
/// branch_and_bound_dilations(grid, ...) (a clear error otherwise).
CoarseResult coarse_search_branch_and_bound(const NearField& field, const Points2& points, const Pose2& centre,
                                            const PoseGrid& grid);

}  // namespace lookahead::slam::segslam
