// SPDX-License-Identifier: MIT
// The coarse search that seeds SegSLAM 3D matching's ICP (SegSLAM sec. 4.5; the deviations are
// stated in octree_submap_ops.hpp): on a grid of level poses around a guess (x, y, yaw; z
// stays the guess's), the pose that puts the most window points near a candidate's surfaces
// in the plane (NearOccupiedField::near_in_plane). The 3D counterpart of coarse_search.hpp,
// and like it two searches that return the same pose: the exhaustive one and a branch and
// bound over blocks of 2^h x 2^h translations whose bound reads the field's bound levels.
#pragma once

#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/segslam/near_occupied_field.hpp"
#include "lookahead/slam/segslam/point_icp3.hpp"

namespace lookahead::slam::segslam {

/// Poses guess + (i step, j step, 0, a angle_step) for |i|, |j| <= radius / step and
/// |a| <= angle / angle_step.
struct LevelPoseGrid {
  double radius = 2.0, step = 0.3;         ///< [m]
  double angle = 0.25, angle_step = 0.05;  ///< [rad]
};

struct LevelCoarseResult {
  Pose4 pose;     ///< the guess itself unless a grid pose scores more
  int score = 0;  ///< points near a surface in the plane at `pose`
};

/// The NearOccupiedField bound widths (one per level above 0) the branch and bound needs for
/// grids of `step` [m] on a map of `resolution` [m].
std::vector<int> level_bound_widths(double step, double resolution);

/// Points near a surface in the plane with the robot at `pose`.
int near_in_plane_count(const NearOccupiedField& field, const Pose4& pose, const Points3& points);

/// Every pose of the grid; a pose replaces the guess only when it scores more, ties go to
/// the first in (yaw, x, y) order.
LevelCoarseResult level_search_exhaustive(const NearOccupiedField& field, const Points3& points, const Pose4& guess,
                                          const LevelPoseGrid& grid);

/// The same result (same tie-breaking, bit for bit) by branch and bound; `field` must hold
/// the bound levels of level_bound_widths(grid.step, ...) (a clear error otherwise).
LevelCoarseResult level_search_branch_and_bound(const NearOccupiedField& field, const Points3& points,
                                                const Pose4& guess, const LevelPoseGrid& grid);

/// Up to `count` distinct peaks of the grid, best first: the first is the branch and bound's
/// best pose, each next one the best pose farther than `separation` [m] in the plane or
/// `angle_separation` [rad] in yaw from every earlier peak (by branch and bound with those
/// poses scored 0, so the bounds stay bounds). Fewer when no pose scores above 0. Unlike
/// level_search_branch_and_bound the guess does not stand in for a grid pose.
std::vector<LevelCoarseResult> level_search_peaks(const NearOccupiedField& field, const Points3& points,
                                                  const Pose4& guess, const LevelPoseGrid& grid, std::size_t count,
                                                  double separation, double angle_separation);

/// A part of a level pose grid: its poses within +-radius [m] of `centre` in x and in y and
/// within +-angle [rad] of its yaw.
struct LevelSubgrid {
  Pose4 centre;
  double radius = 0.0;
  double angle = 0.0;
};

/// The part around `first` that holds every part of `parts` (first.centre, the largest offset
/// plus reach in x or y, and in yaw up to pi): the grid several parts are searched on together.
LevelSubgrid covering_subgrid(const LevelSubgrid& first, const std::vector<LevelSubgrid>& parts);

/// level_search_peaks in each part of one grid, the parts sharing the scores and bounds they
/// have in common (one part spanning the grid is level_search_peaks bit for bit). Why: the
/// wide re-entry searches of several particles over one candidate (wide_reentry.hpp) cover
/// overlapping squares; each must find its own best peaks, and most of the cost is scoring.
std::vector<std::vector<LevelCoarseResult>> level_search_peaks_within(
    const NearOccupiedField& field, const Points3& points, const Pose4& guess, const LevelPoseGrid& grid,
    const std::vector<LevelSubgrid>& parts, std::size_t count, double separation, double angle_separation);

}  // namespace lookahead::slam::segslam
