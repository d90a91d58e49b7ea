// SPDX-License-Identifier: MIT
// Matching a look-ahead window to a candidate submap by a separate localisation particle
// filter (Fairfield et al. 2010, SegSLAM sec. 4.5.2, eq. 19) in 3D: the counterpart of the 2D
// localize_window (grid_submap_ops.hpp), chosen by matching.use_localization_filter in place
// of the coarse search and ICP (match_window). Created for one match and discarded.
//
// The cloud starts around the guess with the candidate's uncertainty (half the capped
// search's reach as one sigma, the reach widening with the error since the candidate:
// candidate_reach.hpp), and passes over the window's end points with the 3D RBPF's
// measurement model (octree_likelihood.hpp), resampling and jittering (annealed: three passes,
// shrinking jitter). SegSLAM eq. (19): w = p(err_X) p(|Sigma_X|) p(tau^2).
//
// Deviations: err_X is the structure points' mean error at the cloud's mean (SegSLAM eq. (18)'s err
// here, so the two weights compare and the same acceptance tests apply: structure_fit.hpp),
// not the squared measurement error; the window's end points are taken in three consecutive
// parts (the window's sweeps, about) rather than sweep by sweep with their motion, since the
// window is already one cloud in the frame of its first sweep. The measurement model is not
// tempered by the filter's weight exponent (as in 2D): tempered, the cloud stayed about 9 cm
// wide on the garage drive and p(|Sigma_X|) took four fifths of a right match's weight.
// |Sigma_X| is that of x and y (as in 2D); the height is estimated too (a narrow prior).
#pragma once

#include <cstdint>

#include "lookahead/slam/octree/octree_likelihood.hpp"
#include "lookahead/slam/segslam/octree_submap_ops.hpp"

namespace lookahead::slam::segslam {

/// The localisation filter's match of `window` to `candidate` (whose match target is
/// `target`) from `guess`: the cloud's mean pose, its structure fit and acceptance tests,
/// `spread_factor` = p(|Sigma_X|) (a cloud of one icp_sigma in x and y keeps exp(-1/2)) and
/// weight = spread_factor x SegSLAM eq. (18). The same seed gives the same match.
WindowMatch3 localize_window3(const EvidenceOctree& candidate, const OctreeMatchTarget& target,
                              const SweepWindow& window, const Pose4& guess, const MatchingOptions& options,
                              const OctreeLikelihoodOptions& likelihood, const StructureTestOptions& structure,
                              std::uint64_t seed);

}  // namespace lookahead::slam::segslam
