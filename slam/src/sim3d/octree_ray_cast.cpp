// SPDX-License-Identifier: MIT
#include "lookahead/slam/sim3d/octree_ray_cast.hpp"

#include <cmath>
#include <limits>

namespace lookahead::slam {

std::optional<double> cast_ray(const EvidenceOctree& world, const Eigen::Vector3d& origin,
                               const Eigen::Vector3d& dir, double max_range) {
  const OctreeGrid& g = world.grid();
  const auto occupied_above = static_cast<float>(world.options().occupied_above);
  OctreeReader reader(world);
  long key[3] = {g.axis_key(origin.x()), g.axis_key(origin.y()), g.axis_key(origin.z())};
  int step[3];
  double t_next[3], t_delta[3];
  for (int a = 0; a < 3; ++a) {
    step[a] = dir[a] > 0.0 ? 1 : (dir[a] < 0.0 ? -1 : 0);
    if (step[a] == 0) {
      t_next[a] = t_delta[a] = std::numeric_limits<double>::infinity();
      continue;
    }
    const double boundary = g.axis_centre(static_cast<int>(key[a])) + 0.5 * g.resolution() * step[a];
    t_next[a] = (boundary - origin[a]) / dir[a];
    t_delta[a] = g.resolution() / std::abs(dir[a]);
  }
  double t = 0.0;  // where the beam entered the current voxel
  while (t <= max_range) {
    const std::optional<float> l = reader.log_odds(static_cast<int>(key[0]), static_cast<int>(key[1]),
                                                   static_cast<int>(key[2]));
    if (l && *l > occupied_above) return t;
    const int a = t_next[0] < t_next[1] ? (t_next[0] < t_next[2] ? 0 : 2) : (t_next[1] < t_next[2] ? 1 : 2);
    t = t_next[a];
    key[a] += step[a];
    t_next[a] += t_delta[a];
    if (!OctreeGrid::in_range(key[a])) break;
  }
  return std::nullopt;
}

}  // namespace lookahead::slam
