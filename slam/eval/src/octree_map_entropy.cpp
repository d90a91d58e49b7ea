// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/octree_map_entropy.hpp"

#include <cmath>

namespace lookahead::slam {

double voxel_entropy(double log_odds) {
  const double p = 1.0 / (1.0 + std::exp(-log_odds));
  if (p <= 0.0 || p >= 1.0) return 0.0;  // the limit of p log p
  return -(p * std::log(p) + (1.0 - p) * std::log(1.0 - p));
}

double octree_map_entropy(const EvidenceOctree& map) {
  double h = 0.0;
  map.for_each_voxel([&](const OctreeKey&, float l) { h += voxel_entropy(l); });
  return h * std::pow(map.grid().resolution(), 3);
}

}  // namespace lookahead::slam
