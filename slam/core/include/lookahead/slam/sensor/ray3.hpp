// SPDX-License-Identifier: MIT
// One 3D laser beam: what a range sweep holds and what ray insertion casts into the octree.
#pragma once

#include <Eigen/Core>

namespace lookahead::slam {

/// One beam in the map frame. `hit` false: a no-return, which clears space only.
struct Ray3 {
  Eigen::Vector3d origin;
  Eigen::Vector3d end;
  bool hit = true;
};

}  // namespace lookahead::slam
