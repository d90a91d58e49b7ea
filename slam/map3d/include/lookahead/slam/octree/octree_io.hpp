// SPDX-License-Identifier: MIT
// EvidenceOctree <-> OctoMap files, through liboctomap (the adapter: no OctoMap type leaks
// into the octree headers). .bt stores each voxel as free or occupied (octovis reads it);
// .ot keeps the log-odds. Bad files raise ParseError naming the file.
#pragma once

#include <string>

#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

/// Reads a .bt or .ot OcTree. The map takes the file's resolution and, for .ot, its
/// update and clamping parameters; pruned (merged) leaves are expanded into voxels.
EvidenceOctree read_octomap(const std::string& path);

/// Writes DIR/NAME.bt or .ot, chosen by the extension of `path`.
void write_octomap(const EvidenceOctree& map, const std::string& path);

}  // namespace lookahead::slam
