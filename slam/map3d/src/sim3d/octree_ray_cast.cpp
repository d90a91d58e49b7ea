// SPDX-License-Identifier: MIT
#include "lookahead/slam/sim3d/octree_ray_cast.hpp"

#include "octree/voxel_walk.hpp"

namespace lookahead::slam {

std::optional<double> cast_ray(const EvidenceOctree& world, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                               double max_range) {
  const OctreeGrid& g = world.grid();
  const auto occupied_above = static_cast<float>(world.options().occupied_above);
  OctreeReader reader(world);
  VoxelWalk walk(g, origin, dir);
  double t = 0.0;  // where the beam entered the current voxel
  while (t <= max_range) {
    if (!OctreeGrid::in_range(walk.key(0)) || !OctreeGrid::in_range(walk.key(1)) || !OctreeGrid::in_range(walk.key(2)))
      break;
    const std::optional<float> l =
        reader.log_odds(static_cast<int>(walk.key(0)), static_cast<int>(walk.key(1)), static_cast<int>(walk.key(2)));
    if (l && *l > occupied_above) return t;
    t = walk.step();
  }
  return std::nullopt;
}

}  // namespace lookahead::slam
