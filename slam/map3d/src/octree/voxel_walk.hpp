// SPDX-License-Identifier: MIT
// The voxels a ray crosses, in order: a 3D DDA over voxel boundaries (Amanatides and Woo,
// "A fast voxel traversal algorithm for ray tracing", 1987). Ray insertion and the
// simulator's ray casting both walk with it.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "lookahead/slam/octree/octree_key.hpp"

namespace lookahead::slam {

class VoxelWalk {
 public:
  /// Starts in the voxel of `from`; `dir` is a unit vector.
  VoxelWalk(const OctreeGrid& grid, const Eigen::Vector3d& from, const Eigen::Vector3d& dir) {
    for (int a = 0; a < 3; ++a) {
      key_[a] = grid.axis_key(from[a]);
      step_[a] = dir[a] > 0.0 ? 1 : (dir[a] < 0.0 ? -1 : 0);
      if (step_[a] == 0) {
        next_[a] = delta_[a] = std::numeric_limits<double>::infinity();
        continue;
      }
      const double boundary = grid.axis_centre(static_cast<int>(key_[a])) + 0.5 * grid.resolution() * step_[a];
      next_[a] = (boundary - from[a]) / dir[a];
      delta_[a] = grid.resolution() / std::abs(dir[a]);
    }
  }

  /// Key of the current voxel along axis a (may leave the key range; check in_range).
  [[nodiscard]] long key(int a) const { return key_[a]; }
  /// Distance along the ray at which it leaves the current voxel [m].
  [[nodiscard]] double exit_distance() const { return next_[axis()]; }
  /// Moves into the next voxel; returns the distance at which the ray enters it [m].
  double step() {
    const int a = axis();
    const double entered = next_[a];
    key_[a] += step_[a];
    next_[a] += delta_[a];
    return entered;
  }

 private:
  [[nodiscard]] int axis() const {
    return next_[0] < next_[1] ? (next_[0] < next_[2] ? 0 : 2) : (next_[1] < next_[2] ? 1 : 2);
  }

  long key_[3];
  int step_[3];
  double next_[3], delta_[3];  ///< distance to the next boundary; between boundaries
};

}  // namespace lookahead::slam
