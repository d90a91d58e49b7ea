// SPDX-License-Identifier: MIT
// SegSLAM eq. (22) (Fairfield et al. 2010) on an evidence octree: the binary entropy of every
// observed voxel, times gamma = the voxel volume [nats m^3]. The 3D RBPF's best map is scored
// with it against SegSLAM's minimum-entropy map sample (OctreeCanvas::entropy, the same sum).
#pragma once

#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

/// The binary entropy [nats] of a voxel with these log-odds (0 for a certain one).
double voxel_entropy(double log_odds);

/// Sum of voxel_entropy over the observed voxels of `map` times the voxel volume [nats m^3].
double octree_map_entropy(const EvidenceOctree& map);

}  // namespace lookahead::slam
