// SPDX-License-Identifier: MIT
// Kullback-Leibler divergence of one occupancy map from a reference map (P-SLAM, Chang et
// al. 2007, P-SLAM eq. (24): D_KL(P || Q) = sum_i P(i) log(P(i) / Q(i)), P the reference). Each cell
// is a Bernoulli variable, so a cell contributes p log(p / q) + (1 - p) log((1 - p) / (1 - q)).
// Both maps must share their frame (runs of the same log start at the same pose); cells
// observed in both are compared, probabilities clamped to [0.001, 0.999]. Natural log.
#pragma once

#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::slam {

struct MapDivergence {
  double total = 0.0;        ///< [nats]
  std::size_t compared = 0;  ///< cells observed in both maps
};

MapDivergence map_divergence(const ProbabilityMap& reference, const ProbabilityMap& map);

}  // namespace lookahead::slam
