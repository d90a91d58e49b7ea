// SPDX-License-Identifier: MIT
// Eq. 22 on an evidence octree (the 3D RBPF's map entropy), against hand values and against
// the SegSLAM map-sample canvas, which must score the same map the same.
#include "lookahead/slam/eval/octree_map_entropy.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lookahead/slam/segslam/octree_submap_ops.hpp"

namespace lookahead::slam {
namespace {

TEST(OctreeMapEntropy, SumsTheBinaryEntropyOfObservedVoxelsTimesTheVoxelVolume) {
  EXPECT_NEAR(voxel_entropy(0.0), std::log(2.0), 1e-12);
  EXPECT_NEAR(voxel_entropy(2.0), voxel_entropy(-2.0), 1e-12);
  EXPECT_LT(voxel_entropy(3.5), voxel_entropy(0.85));
  EXPECT_EQ(voxel_entropy(800.0), 0.0);
  EvidenceOctree map;                       // 0.2 m voxels
  EXPECT_EQ(octree_map_entropy(map), 0.0);  // unobserved space carries no entropy
  const OctreeGrid& g = map.grid();
  map.set_log_odds(*g.key_of({1.0, 0.0, 0.0}), 0.0F);
  map.set_log_odds(*g.key_of({0.0, 2.0, 0.5}), 2.0F);
  const double volume = std::pow(g.resolution(), 3);
  EXPECT_NEAR(octree_map_entropy(map), (std::log(2.0) + voxel_entropy(2.0)) * volume, 1e-9);
  // A map pasted alone, in its own frame, is the same map to the SegSLAM canvas.
  segslam::OctreeCanvas canvas(map.options());
  canvas.paste(map, Pose4{});
  EXPECT_NEAR(canvas.entropy(), octree_map_entropy(map), 1e-9);
}

}  // namespace
}  // namespace lookahead::slam
