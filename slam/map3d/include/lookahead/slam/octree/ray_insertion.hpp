// SPDX-License-Identifier: MIT
// Inserting range measurements into an evidence octree: every voxel a beam crosses gets
// one miss, the voxel it ends in one hit (SegSLAM sec. 2.1, "ray insertion").
//
// The update is two-phase like octomap::OcTree::insertPointCloud: first the voxels of the
// whole batch are collected and de-duplicated (a voxel that any beam ends in is occupied
// and not also free), then each is updated once. So a voxel near the sensor that a hundred
// beams cross gets one miss per batch, not a hundred.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/octree/evidence_octree.hpp"
#include "lookahead/slam/sensor/ray3.hpp"

namespace lookahead::slam {

struct RayInsertOptions {
  /// Beams are used up to this length [m]; longer ones are cut there and mark free space
  /// only (OctoMap's maxrange). > 0.
  double max_range = 15.0;
};

/// The voxels one batch of rays observes, de-duplicated, occupied winning over free.
struct RayVoxels {
  std::vector<OctreeKey> free;
  std::vector<OctreeKey> occupied;
};

/// Appends the voxels strictly between the voxel of `from` and the voxel of `to` (the
/// first included, the last not) to `out`: a 3D DDA over voxel boundaries.
void trace_voxels(const OctreeGrid& grid, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                  std::vector<OctreeKey>& out);

/// Phase one: the voxels a batch observes, in brick order (writes then stay in one brick
/// for as long as possible).
RayVoxels collect_ray_voxels(const OctreeGrid& grid, const std::vector<Ray3>& rays, const RayInsertOptions& options);

/// Both phases.
void insert_rays(EvidenceOctree& map, const std::vector<Ray3>& rays, const RayInsertOptions& options);

}  // namespace lookahead::slam
