// SPDX-License-Identifier: MIT
// Ray insertion against the reference: octomap::OcTree::insertPointCloud on the same rays.
#include "lookahead/slam/octree/ray_insertion.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <tuple>

namespace lookahead::slam {
namespace {

// Random beams from a few sensor positions into a box room, some longer than max range.
std::vector<std::vector<Ray3>> random_scans(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::vector<Ray3>> scans;
  for (int s = 0; s < 4; ++s) {
    const Eigen::Vector3d origin(0.3 * s + 0.05, 0.11 * s - 0.2, 0.73);
    std::vector<Ray3> rays;
    for (int i = 0; i < 2000; ++i) {
      Eigen::Vector3d d(u(rng), u(rng), 0.4 * u(rng));
      d.normalize();
      const double range = 1.0 + 9.0 * (0.5 + 0.5 * u(rng));
      rays.push_back({origin, origin + d * range, true});
    }
    scans.push_back(rays);
  }
  return scans;
}

TEST(RayInsertion, AgreesWithOctoMapInsertPointCloud) {
  const RayInsertOptions options{8.0};
  EvidenceOctree ours(OctreeOptions{});  // OctoMap's default update and clamping values
  octomap::OcTree ref(ours.options().resolution);
  for (const std::vector<Ray3>& scan : random_scans(7)) {
    insert_rays(ours, scan, options);
    octomap::Pointcloud cloud;
    for (const Ray3& r : scan)
      cloud.push_back(static_cast<float>(r.end.x()), static_cast<float>(r.end.y()), static_cast<float>(r.end.z()));
    const Eigen::Vector3d& o = scan.front().origin;
    ref.insertPointCloud(
        cloud, octomap::point3d(static_cast<float>(o.x()), static_cast<float>(o.y()), static_cast<float>(o.z())),
        options.max_range);
  }
  // Compare the classification of every voxel either map knows.
  std::size_t both = 0, agree = 0, only_ours = 0, only_ref = 0;
  ours.for_each_voxel([&](const OctreeKey& k, float l) {
    const octomap::OcTreeNode* n = ref.search(octomap::OcTreeKey(k.x, k.y, k.z));
    if (!n) {
      ++only_ours;
      return;
    }
    ++both;
    if ((l > 0.0f) == ref.isNodeOccupied(n)) ++agree;
  });
  for (auto it = ref.begin_leafs(); it != ref.end_leafs(); ++it) {
    const octomap::OcTreeKey k = it.getKey();
    if (!ours.log_odds({k[0], k[1], k[2]})) ++only_ref;
  }
  const double known = static_cast<double>(both + only_ours + only_ref);
  std::printf("voxels known to both %zu, same class %zu, only ours %zu, only OctoMap %zu\n", both, agree, only_ours,
              only_ref);
  // Tolerance: our DDA and OctoMap's differ only where a beam passes within rounding of a
  // voxel corner, so a handful of voxels per thousand may differ.
  EXPECT_GT(both, 10000U);
  EXPECT_GE(static_cast<double>(agree) / static_cast<double>(both), 0.995);
  EXPECT_LE(static_cast<double>(only_ours + only_ref) / known, 0.005);
}

TEST(RayInsertion, TraceStopsBeforeTheEndVoxel) {
  const OctreeGrid grid(0.2);
  std::vector<OctreeKey> out;
  trace_voxels(grid, {0.1, 0.1, 0.1}, {1.1, 0.1, 0.1}, out);
  ASSERT_EQ(out.size(), 5U);  // voxels 0..4; voxel 5 holds the end point
  EXPECT_EQ(out.front(), *grid.key_of({0.1, 0.1, 0.1}));
  EXPECT_EQ(out.back().x, grid.key_of({0.9, 0.1, 0.1})->x);
}

TEST(RayInsertion, LongBeamsClearOnlyUpToMaxRange) {
  EvidenceOctree map;
  insert_rays(map, {{{0.1, 0.1, 0.1}, {20.1, 0.1, 0.1}, true}}, RayInsertOptions{5.0});
  EXPECT_EQ(map.state(*map.grid().key_of({4.5, 0.1, 0.1})), VoxelState::kFree);
  EXPECT_EQ(map.state(*map.grid().key_of({6.0, 0.1, 0.1})), VoxelState::kUnknown);
  EXPECT_EQ(map.state(*map.grid().key_of({20.1, 0.1, 0.1})), VoxelState::kUnknown);
}

TEST(RayInsertion, OccupiedWinsOverFreeInOneBatch) {
  EvidenceOctree map;
  // The first beam ends where the second passes: the voxel is occupied, with one hit.
  insert_rays(map, {{{0.1, 0.1, 0.1}, {2.1, 0.1, 0.1}, true}, {{0.1, 0.1, 0.1}, {4.1, 0.1, 0.1}, true}},
              RayInsertOptions{});
  const auto l = map.log_odds(*map.grid().key_of({2.1, 0.1, 0.1}));
  ASSERT_TRUE(l);
  EXPECT_FLOAT_EQ(*l, static_cast<float>(map.options().log_odds_hit));
  EXPECT_FLOAT_EQ(*map.log_odds(*map.grid().key_of({1.0, 0.1, 0.1})), static_cast<float>(map.options().log_odds_miss));
}

// Phase one against a plain reference (std::set of the traced and end voxels): each voxel
// once, occupied and free disjoint, and in brick order (the radix sort's result is std::sort's).
TEST(RayInsertion, CollectedVoxelsAreUniqueInBrickOrderAndComplete) {
  const auto tuple = [](const OctreeKey& k) { return std::make_tuple(k.x, k.y, k.z); };
  const auto brick = [](const OctreeKey& k) {
    return std::make_tuple(k.x >> octree_detail::kBrickBits, k.y >> octree_detail::kBrickBits,
                           k.z >> octree_detail::kBrickBits);
  };
  for (unsigned seed : {1U, 2U}) {
    EvidenceOctree map;
    const RayInsertOptions options{6.0};
    std::vector<Ray3> rays;
    for (const auto& scan : random_scans(seed)) rays.insert(rays.end(), scan.begin(), scan.end());
    const RayVoxels v = collect_ray_voxels(map.grid(), rays, options);
    std::set<std::tuple<int, int, int>> occupied, free;
    for (const Ray3& r : rays) {
      const Eigen::Vector3d d = r.end - r.origin;
      const double length = d.norm();
      if (r.hit && length <= options.max_range) occupied.insert(tuple(*map.grid().key_of(r.end)));
      std::vector<OctreeKey> trace;
      trace_voxels(map.grid(), r.origin, r.origin + d * (std::min(length, options.max_range) / length), trace);
      for (const OctreeKey& k : trace) free.insert(tuple(k));
    }
    for (const auto& k : occupied) free.erase(k);
    for (const std::vector<OctreeKey>* keys : {&v.occupied, &v.free}) {
      for (std::size_t i = 1; i < keys->size(); ++i) {
        ASSERT_LE(brick((*keys)[i - 1]), brick((*keys)[i])) << i;
        ASSERT_NE(tuple((*keys)[i - 1]), tuple((*keys)[i])) << i;
      }
    }
    std::set<std::tuple<int, int, int>> got_occupied, got_free;
    for (const OctreeKey& k : v.occupied) got_occupied.insert(tuple(k));
    for (const OctreeKey& k : v.free) got_free.insert(tuple(k));
    EXPECT_EQ(got_occupied.size(), v.occupied.size());
    EXPECT_EQ(got_occupied, occupied);
    EXPECT_EQ(got_free, free);
  }
}

}  // namespace
}  // namespace lookahead::slam
