// SPDX-License-Identifier: MIT
// Casting a simulated beam into a world octree: the distance to the first occupied voxel.
#pragma once

#include <optional>

#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

/// Range [m] along the unit vector `dir` from `origin` to the first occupied voxel (the
/// distance at which the beam enters it); nullopt when none lies within `max_range`.
std::optional<double> cast_ray(const EvidenceOctree& world, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                               double max_range);

}  // namespace lookahead::slam
