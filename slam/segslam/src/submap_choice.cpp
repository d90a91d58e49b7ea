// SPDX-License-Identifier: MIT
#include "submap_choice.hpp"

#include <cmath>

namespace lookahead::slam::segslam {

double match_weight(double icp_error, double translation, const MatchingOptions& o) {
  const double e = icp_error / o.icp_sigma;
  const double t = translation / o.translation_sigma;
  return std::exp(-0.5 * (e * e + t * t));
}

double null_match_weight(const MatchingOptions& o) { return match_weight(o.null_error, 0.0, o); }

ChoiceDraw draw_submap_choice(bool segment, const std::vector<double>& match_weights, const MatchingOptions& o,
                              std::mt19937_64& rng) {
  const SubmapChoice null_choice = segment ? SubmapChoice::kNew : SubmapChoice::kSame;
  if (match_weights.empty()) return {null_choice, 0};
  double total = null_match_weight(o);
  for (double w : match_weights) total += w;
  double r = std::uniform_real_distribution<double>(0.0, total)(rng) - null_match_weight(o);
  if (r < 0) return {null_choice, 0};
  for (std::size_t i = 0; i < match_weights.size(); ++i) {
    r -= match_weights[i];
    if (r < 0) return {SubmapChoice::kMatch, i};
  }
  return {SubmapChoice::kMatch, match_weights.size() - 1};
}

}  // namespace lookahead::slam::segslam
