// SPDX-License-Identifier: MIT
// Map entropy H(m) = -sum_c [p_c log p_c + (1 - p_c) log(1 - p_c)] over observed cells
// (Fairfield et al. 2010, SegSLAM eq. (22); the measure of Stachniss et al.). Natural log.
#pragma once

#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::slam {

struct MapEntropy {
  double total = 0.0;        ///< [nats]
  std::size_t observed = 0;  ///< cells with a probability
  [[nodiscard]] double per_cell() const { return observed ? total / static_cast<double>(observed) : 0.0; }
};

MapEntropy map_entropy(const ProbabilityMap& map);

}  // namespace lookahead::slam
