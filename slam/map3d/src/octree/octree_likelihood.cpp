// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_likelihood.hpp"

#include <cmath>
#include <stdexcept>

namespace lookahead::slam {

void OctreeLikelihoodOptions::validate() const {
  if (!(sigma > 0.0)) throw std::invalid_argument("likelihood: sigma must be > 0");
  if (!(random_floor > 0.0 && random_floor < 1.0))
    throw std::invalid_argument("likelihood: random_floor must be in (0, 1)");
  if (!(unknown_likelihood > 0.0 && unknown_likelihood < 1.0))
    throw std::invalid_argument("likelihood: unknown_likelihood must be in (0, 1)");
}

double octree_log_likelihood(const EvidenceOctree& map, const std::vector<Eigen::Vector3d>& ends,
                             const OctreeLikelihoodOptions& options) {
  const OctreeGrid& grid = map.grid();
  const auto occupied_above = static_cast<float>(map.options().occupied_above);
  const double inv_two_sigma2 = 1.0 / (2.0 * options.sigma * options.sigma);
  const double log_unknown = std::log(options.unknown_likelihood);
  OctreeReader reader(map);
  double sum = 0.0;
  for (const Eigen::Vector3d& p : ends) {
    const long kx = grid.axis_key(p.x()), ky = grid.axis_key(p.y()), kz = grid.axis_key(p.z());
    double best_d2 = std::numeric_limits<double>::infinity();
    bool any_known = false;
    for (long dz = -1; dz <= 1; ++dz) {
      for (long dy = -1; dy <= 1; ++dy) {
        for (long dx = -1; dx <= 1; ++dx) {
          const std::optional<float> l =
              reader.log_odds(static_cast<int>(kx + dx), static_cast<int>(ky + dy), static_cast<int>(kz + dz));
          if (!l) continue;
          any_known = true;
          if (*l <= occupied_above) continue;
          const Eigen::Vector3d c(grid.axis_centre(static_cast<int>(kx + dx)),
                                  grid.axis_centre(static_cast<int>(ky + dy)),
                                  grid.axis_centre(static_cast<int>(kz + dz)));
          best_d2 = std::min(best_d2, (c - p).squaredNorm());
        }
      }
    }
    if (!any_known) {
      sum += log_unknown;
      continue;
    }
    sum += std::log(std::exp(-best_d2 * inv_two_sigma2) + options.random_floor);
  }
  return sum;
}

}  // namespace lookahead::slam
