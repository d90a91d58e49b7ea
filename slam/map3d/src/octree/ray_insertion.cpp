// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/ray_insertion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "voxel_walk.hpp"

namespace lookahead::slam {
namespace {

using octree_detail::kBrickBits;

// A key packed so that sorting groups the voxels of one brick together.
std::uint64_t pack(const OctreeKey& k) {
  const auto b = [](int v) { return static_cast<std::uint64_t>(v >> kBrickBits); };
  return (b(k.x) << 34) | (b(k.y) << 20) | (b(k.z) << 6) |
         static_cast<std::uint64_t>(octree_detail::voxel_index(k.x, k.y, k.z));
}

OctreeKey unpack(std::uint64_t p) {
  const auto v = static_cast<int>(p & 63U);
  const auto brick = [&](int shift) { return static_cast<int>((p >> shift) & 0x3FFFU) << kBrickBits; };
  return {static_cast<std::uint16_t>(brick(34) | (v & 3)), static_cast<std::uint16_t>(brick(20) | ((v >> 2) & 3)),
          static_cast<std::uint16_t>(brick(6) | ((v >> 4) & 3))};
}

// Sorts and removes duplicates: the same result as std::sort + std::unique, by a least
// significant digit radix sort (11-bit digits over the 48 bits a packed key uses), which took
// about a quarter of a 3D filter's time as std::sort (perf, 20 particles). A digit that all keys
// share (most high ones: a sweep spans few bricks) is skipped.
void sort_unique(std::vector<std::uint64_t>& v) {
  constexpr int kDigitBits = 11;
  constexpr int kPasses = 5;  // 55 >= 48 bits
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  if (v.size() < 2) return;
  thread_local std::vector<std::uint64_t> scratch;
  scratch.resize(v.size());
  for (int pass = 0; pass < kPasses; ++pass) {
    const int shift = pass * kDigitBits;
    std::array<std::size_t, kBuckets> start{};
    for (const std::uint64_t x : v) ++start[(x >> shift) & (kBuckets - 1)];
    if (start[(v.front() >> shift) & (kBuckets - 1)] == v.size()) continue;
    std::size_t sum = 0;
    for (std::size_t& c : start) sum += std::exchange(c, sum);
    for (const std::uint64_t x : v) scratch[start[(x >> shift) & (kBuckets - 1)]++] = x;
    v.swap(scratch);
  }
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

void trace_voxels(const OctreeGrid& grid, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                  std::vector<OctreeKey>& out) {
  const std::optional<OctreeKey> start = grid.key_of(from);
  const std::optional<OctreeKey> stop = grid.key_of(to);
  if (!start || !stop || *start == *stop) return;
  const Eigen::Vector3d delta = to - from;
  const double length = delta.norm();
  VoxelWalk walk(grid, from, delta / length);
  const long goal[3] = {stop->x, stop->y, stop->z};
  // At most one voxel per boundary crossed; the bound guards against rounding at the goal.
  const long max_steps = std::abs(goal[0] - start->x) + std::abs(goal[1] - start->y) + std::abs(goal[2] - start->z);
  for (long i = 0; i < max_steps; ++i) {
    out.push_back({static_cast<std::uint16_t>(walk.key(0)), static_cast<std::uint16_t>(walk.key(1)),
                   static_cast<std::uint16_t>(walk.key(2))});
    if (walk.exit_distance() > length) break;
    walk.step();
    if (walk.key(0) == goal[0] && walk.key(1) == goal[1] && walk.key(2) == goal[2]) break;
  }
}

RayVoxels collect_ray_voxels(const OctreeGrid& grid, const std::vector<Ray3>& rays, const RayInsertOptions& options) {
  std::vector<OctreeKey> trace;
  std::vector<std::uint64_t> free, occupied;
  for (const Ray3& r : rays) {
    trace.clear();
    const Eigen::Vector3d d = r.end - r.origin;
    const double length = d.norm();
    if (r.hit && length <= options.max_range) {
      trace_voxels(grid, r.origin, r.end, trace);
      if (const auto k = grid.key_of(r.end)) occupied.push_back(pack(*k));
    } else if (length > 0.0) {
      trace_voxels(grid, r.origin, r.origin + d * (std::min(length, options.max_range) / length), trace);
    }
    for (const OctreeKey& k : trace) free.push_back(pack(k));
  }
  sort_unique(free);
  sort_unique(occupied);
  RayVoxels out;
  out.occupied.reserve(occupied.size());
  for (std::uint64_t p : occupied) out.occupied.push_back(unpack(p));
  // Occupied wins: a voxel that one beam ends in is not also cleared by another.
  std::vector<std::uint64_t> only_free;
  only_free.reserve(free.size());
  std::set_difference(free.begin(), free.end(), occupied.begin(), occupied.end(), std::back_inserter(only_free));
  out.free.reserve(only_free.size());
  for (std::uint64_t p : only_free) out.free.push_back(unpack(p));
  return out;
}

void insert_rays(EvidenceOctree& map, const std::vector<Ray3>& rays, const RayInsertOptions& options) {
  const RayVoxels voxels = collect_ray_voxels(map.grid(), rays, options);
  OctreeWriter writer(map);
  for (const OctreeKey& k : voxels.free) writer.update(k, false);
  for (const OctreeKey& k : voxels.occupied) writer.update(k, true);
}

}  // namespace lookahead::slam
