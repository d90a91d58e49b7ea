// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/map_entropy.hpp"

#include <cmath>

namespace lookahead::slam {

MapEntropy map_entropy(const ProbabilityMap& map) {
  MapEntropy h;
  for (const double p : map.p) {
    if (p < 0) continue;  // unknown cells carry no observation
    ++h.observed;
    if (p <= 0.0 || p >= 1.0) continue;  // certain cells add nothing (limit of p log p)
    h.total -= p * std::log(p) + (1.0 - p) * std::log(1.0 - p);
  }
  return h;
}

}  // namespace lookahead::slam
