// SPDX-License-Identifier: MIT
// A 2D picture of a 3D map seen from above: a column is drawn as a wall when it holds at
// least `wall_height` metres of occupied voxels (so floors, decks and roofs, a voxel or
// two thick, do not blacken the picture), free when a beam passed through it.
#pragma once

#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

/// `upsample` pixels per voxel side, so a coarse map still makes a readable picture.
ProbabilityMap top_view(const EvidenceOctree& map, double wall_height = 1.2, int margin_cells = 5, int upsample = 2);

}  // namespace lookahead::slam
