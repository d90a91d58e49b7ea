// SPDX-License-Identifier: MIT
// The nodes of the evidence octree and their reference counts: the "deferred reference
// count octree" (DRCO) of Fairfield et al. 2007, summarised in SegSLAM sec. 2.1.
//
// A node is shared by every map that reaches it; its count says by how many parents. A map
// may change a node in place only when the count is 1 along the whole path from its root;
// otherwise it copies the path first (copy-on-write), so copying a map is one increment
// and a written copy owns exactly the nodes it changed.
//
// Deviation: the leaves are 4x4x4 bricks of voxels rather than single voxels. A brick
// stores 64 log-odds in 272 bytes; a voxel-per-node tree needs a 72-byte node per voxel,
// and the ray loop would chase two more pointers per voxel. The sharing is unchanged, only
// coarser at the bottom. Homogeneous regions are not collapsed (no pruning): a brick
// stores its 64 values even when they are equal.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>

namespace lookahead::slam::octree_detail {

constexpr int kBrickBits = 2;  ///< 4 voxels per brick side
constexpr int kBrickSide = 1 << kBrickBits;
constexpr int kBrickVoxels = kBrickSide * kBrickSide * kBrickSide;  // 64
constexpr int kInnerLevels = 16 - kBrickBits;                       ///< inner levels above the bricks
/// Readers and writers cache the node at this level (32^3 voxels: 6.4 m at 0.2 m), so
/// neighbouring queries descend 3 levels instead of 14.
constexpr int kAnchorLevel = kInnerLevels - 3;
constexpr int kAnchorShift = 16 - kAnchorLevel;

struct NodeBase {
  /// Number of parents (or map roots) pointing here. Atomic: copies of one map are written
  /// from different threads, and they share nodes.
  mutable std::atomic<std::uint32_t> refs{1};
};

struct InnerNode : NodeBase {
  /// Children at level+1: InnerNode above level kInnerLevels-1, Brick below it.
  std::array<NodeBase*, 8> child{};
};

struct Brick : NodeBase {
  std::uint64_t known = 0;  ///< bit i set: voxel i has been observed
  std::array<float, kBrickVoxels> log_odds{};
};

/// Index of the child at inner level `level` (0 = root) that contains key (x, y, z).
inline int child_index(int x, int y, int z, int level) {
  const int bit = 15 - level;
  return ((x >> bit) & 1) | (((y >> bit) & 1) << 1) | (((z >> bit) & 1) << 2);
}
/// Index of a voxel inside its brick.
inline int voxel_index(int x, int y, int z) {
  constexpr int m = kBrickSide - 1;
  return (x & m) | ((y & m) << kBrickBits) | ((z & m) << (2 * kBrickBits));
}

inline void retain(const NodeBase* n) {
  if (n) n->refs.fetch_add(1, std::memory_order_relaxed);
}
/// Drops one reference to `n` (a node at inner level `level`, or a brick when level ==
/// kInnerLevels) and frees it and its unreferenced descendants when it was the last.
void release(const NodeBase* n, int level);
/// A private copy of a node that is shared: the children are shared with the original.
InnerNode* clone(const InnerNode& n);
Brick* clone(const Brick& b);

}  // namespace lookahead::slam::octree_detail
