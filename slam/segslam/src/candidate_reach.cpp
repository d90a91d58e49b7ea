// SPDX-License-Identifier: MIT
#include "candidate_reach.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam::segslam {

MatchingOptions candidate_reach(const MatchingOptions& options, double error_since, double max_search_radius) {
  MatchingOptions o = options;
  const double e = std::max(0.0, error_since);
  o.translation_sigma = std::hypot(options.translation_sigma, e);
  const double reach =
      std::max(options.search_radius, std::min(max_search_radius, std::hypot(options.search_radius, e)));
  // A guess `reach` off may place the robot that much farther from the candidate's path.
  o.proximity_radius = options.proximity_radius + (reach - options.search_radius);
  o.search_radius = reach;
  return o;
}

}  // namespace lookahead::slam::segslam
