// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/evidence_octree.hpp"

#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <random>
#include <thread>

namespace lookahead::slam {
namespace {

OctreeKey key(int x, int y, int z) {
  return {static_cast<std::uint16_t>(32768 + x), static_cast<std::uint16_t>(32768 + y),
          static_cast<std::uint16_t>(32768 + z)};
}

TEST(EvidenceOctree, UnknownUntilObserved) {
  EvidenceOctree map;
  EXPECT_EQ(map.state(key(1, 2, 3)), VoxelState::kUnknown);
  EXPECT_DOUBLE_EQ(map.probability(key(1, 2, 3)), 0.5);
  map.update(key(1, 2, 3), true);
  EXPECT_EQ(map.state(key(1, 2, 3)), VoxelState::kOccupied);
  EXPECT_EQ(map.state(key(1, 2, 4)), VoxelState::kUnknown);  // same brick, not observed
  map.update(key(-5, 0, 0), false);
  EXPECT_EQ(map.state(key(-5, 0, 0)), VoxelState::kFree);
  EXPECT_EQ(map.known_voxels(), 2U);
}

TEST(EvidenceOctree, ClampsLikeOctoMap) {
  EvidenceOctree map;
  for (int i = 0; i < 50; ++i) map.update(key(0, 0, 0), true);
  EXPECT_FLOAT_EQ(*map.log_odds(key(0, 0, 0)), static_cast<float>(map.options().log_odds_max));
  for (int i = 0; i < 50; ++i) map.update(key(0, 0, 0), false);
  EXPECT_FLOAT_EQ(*map.log_odds(key(0, 0, 0)), static_cast<float>(map.options().log_odds_min));
}

TEST(EvidenceOctree, CopySharesEverythingUntilWritten) {
  EvidenceOctree parent;
  for (int i = 0; i < 200; ++i) parent.update(key(i, i / 2, -i / 3), true);
  EvidenceOctree child = parent;  // O(1): one reference count
  const OctreeMemory before = child.memory();
  EXPECT_GT(before.total_bytes, 0U);
  EXPECT_EQ(before.unique_bytes, 0U);
  EXPECT_EQ(EvidenceOctree::distinct_bytes({&parent, &child}), before.total_bytes);
}

TEST(EvidenceOctree, ChildWriteLeavesParentUnchanged) {
  EvidenceOctree parent;
  for (int i = 0; i < 200; ++i) parent.update(key(i, 0, 0), false);
  EvidenceOctree child = parent;
  child.update(key(7, 0, 0), true);
  child.update(key(7, 0, 0), true);
  child.update(key(1000, 3, 3), true);
  EXPECT_EQ(parent.state(key(7, 0, 0)), VoxelState::kFree);
  EXPECT_EQ(child.state(key(7, 0, 0)), VoxelState::kOccupied);
  EXPECT_EQ(parent.state(key(1000, 3, 3)), VoxelState::kUnknown);
  EXPECT_EQ(child.state(key(1000, 3, 3)), VoxelState::kOccupied);
  // The parent is untouched by the child, and the reverse.
  parent.update(key(8, 0, 0), true);
  EXPECT_EQ(child.state(key(8, 0, 0)), VoxelState::kFree);
}

TEST(EvidenceOctree, WrittenChildOwnsOnlyTheChangedPath) {
  EvidenceOctree parent;
  for (int i = 0; i < 4000; i += 4) parent.update(key(i, 0, 0), true);  // 1000 bricks
  EvidenceOctree child = parent;
  child.update(key(0, 0, 0), false);
  const OctreeMemory m = child.memory();
  // One brick and its 14 inner ancestors are private; everything else is shared.
  EXPECT_EQ(m.unique_bytes, sizeof(octree_detail::Brick) + 14 * sizeof(octree_detail::InnerNode));
  EXPECT_EQ(m.total_bytes, parent.memory().total_bytes);
  EXPECT_EQ(EvidenceOctree::distinct_bytes({&parent, &child}), m.total_bytes + m.unique_bytes);
}

// What a copy wrote since it was made, without visiting what it still shares: every voxel of
// a written brick (once), with the base's value where the base observed it.
TEST(EvidenceOctree, VoxelsNotSharedWithTheBaseAreThoseOfWrittenBricks) {
  EvidenceOctree parent;
  for (int i = 0; i < 4000; i += 4) parent.update(key(i, 0, 0), true);  // 1000 bricks
  EvidenceOctree child = parent;
  int visited = 0;
  child.for_each_voxel_not_shared_with(parent, [&](const OctreeKey&, float, std::optional<float>) { ++visited; });
  EXPECT_EQ(visited, 0);                // an unwritten copy shares everything
  child.update(key(0, 0, 0), false);    // a voxel the parent knew (brick 0)
  child.update(key(1, 0, 0), true);     // one it did not, same brick
  child.update(key(9000, 5, 5), true);  // one in a brick the parent never had
  std::map<int, std::pair<float, std::optional<float>>> seen;
  child.for_each_voxel_not_shared_with(parent, [&](const OctreeKey& k, float l, std::optional<float> base) {
    EXPECT_TRUE(seen.emplace(k.x - 32768, std::make_pair(l, base)).second);
  });
  ASSERT_EQ(seen.size(), 3U);
  EXPECT_EQ(seen.at(0).first, *child.log_odds(key(0, 0, 0)));
  EXPECT_EQ(seen.at(0).second, parent.log_odds(key(0, 0, 0)));
  EXPECT_FALSE(seen.at(1).second.has_value());
  EXPECT_FALSE(seen.at(9000).second.has_value());
  // Against an unrelated map, every voxel is visited.
  int all = 0;
  child.for_each_voxel_not_shared_with(EvidenceOctree{}, [&](const OctreeKey&, float, std::optional<float>) { ++all; });
  EXPECT_EQ(static_cast<std::size_t>(all), child.known_voxels());
}

TEST(EvidenceOctree, CopiesWrittenFromTwoThreadsStayIndependent) {
  EvidenceOctree base;
  for (int i = 0; i < 512; ++i) base.update(key(i % 64, i / 64, 0), false);
  std::vector<EvidenceOctree> copies(2, base);
  auto write = [&](int t) {
    std::mt19937 rng(static_cast<unsigned>(t));
    for (int i = 0; i < 20000; ++i)
      copies[t].update(key(static_cast<int>(rng() % 64), static_cast<int>(rng() % 8), t), true);
  };
  std::thread a(write, 0), b(write, 1);
  a.join();
  b.join();
  EXPECT_EQ(base.state(key(0, 0, 1)), VoxelState::kUnknown);
  EXPECT_EQ(copies[0].state(key(0, 0, 1)), VoxelState::kUnknown);
  EXPECT_NE(copies[1].state(key(0, 0, 1)), VoxelState::kUnknown);
  EXPECT_EQ(base.known_voxels(), 512U);
}

}  // namespace
}  // namespace lookahead::slam
