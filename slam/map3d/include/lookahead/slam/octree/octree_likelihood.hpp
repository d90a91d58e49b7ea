// SPDX-License-Identifier: MIT
// How well a map explains a set of beam end points: the particle weight of the 3D RBPF
// (SegSLAM sec. 2.2, the measurement likelihood p(z | x, m)).
//
// A likelihood field truncated to one voxel: an end point's likelihood is a Gaussian in its
// distance to the nearest occupied voxel centre among the 27 voxels around it, floored by a
// random-reading term. Deviation from a full 3D likelihood field: keeping a distance field
// per particle map would make every copy-on-write write also rewrite the field around it;
// one voxel of reach (0.2-0.35 m at 0.2 m voxels) is enough once the motion noise per
// update is below it, and the lookup stays 27 cached reads.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

struct OctreeLikelihoodOptions {
  double sigma = 0.15;              ///< end point std around a surface [m], > 0
  double random_floor = 0.05;       ///< likelihood of an unexplained end point, (0, 1)
  double unknown_likelihood = 0.2;  ///< ... of one with no observed voxel around it, (0, 1)

  void validate() const;
};

/// Sum over end points (map frame) of log p(end point | map).
double octree_log_likelihood(const EvidenceOctree& map, const std::vector<Eigen::Vector3d>& ends,
                             const OctreeLikelihoodOptions& options);

}  // namespace lookahead::slam
