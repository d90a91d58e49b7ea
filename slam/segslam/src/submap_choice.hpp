// SPDX-License-Identifier: MIT
// Sampling a particle's submap (Fairfield et al. 2010, SegSLAM eq. 3):
//   theta ~ p(theta in {same, new, match_1..k} | s_{t-1}, Theta)
// with the matches weighted by SegSLAM eq. (18),
//   w(T_m) ~ p(err_ICP | T_m) p(tau_m^2),
// and the null match (keep the current submap, or start a new one when segmentation fired)
// always among the choices, weighted as a match of error `null_error` and no correction.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

#include "lookahead/slam/segslam/segslam_options.hpp"

namespace lookahead::slam::segslam {

enum class SubmapChoice { kSame, kNew, kMatch };

/// SegSLAM eq. (18) for a match with mean nearest-neighbour error `icp_error` [m] whose transform
/// moved the guess by `translation` [m].
double match_weight(double icp_error, double translation, const MatchingOptions& options);
/// The weight of the null match.
double null_match_weight(const MatchingOptions& options);

struct ChoiceDraw {
  SubmapChoice choice = SubmapChoice::kSame;
  std::size_t match = 0;  ///< index into the match weights when choice == kMatch
};

/// SegSLAM eq. (3): draws among the null choice (kNew when `segment` else kSame) and the matches.
ChoiceDraw draw_submap_choice(bool segment, const std::vector<double>& match_weights, const MatchingOptions& options,
                              std::mt19937_64& rng);

}  // namespace lookahead::slam::segslam
