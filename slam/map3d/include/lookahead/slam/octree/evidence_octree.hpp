// SPDX-License-Identifier: MIT
// 3D evidence grid (log-odds occupancy) stored in a copy-on-write octree: the DRCO map of
// SegSLAM sec. 2.1 (Fairfield, Kantor, Wettergreen 2010; Fairfield et al. 2007).
//
// Copying a map is O(1) (one reference count). Writing to a copy duplicates only the nodes
// on the paths to the bricks it changes; the original never sees the change. Copies may be
// written from different threads; one map object must not be written from two at once.
//
// The update rule and its defaults are OctoMap's (hit 0.7, miss 0.4, clamped to
// [0.1192, 0.971] in probability), so the maps agree with octomap::OcTree on the same rays.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "lookahead/slam/octree/octree_key.hpp"
#include "lookahead/slam/octree/octree_node.hpp"

namespace lookahead::slam {

struct OctreeOptions {
  double resolution = 0.2;           ///< voxel side [m], 0.001..100
  double log_odds_hit = 0.847298;    ///< added where a beam ends: log(0.7/0.3)
  double log_odds_miss = -0.405465;  ///< added where a beam passes: log(0.4/0.6)
  double log_odds_min = -1.99243;    ///< lower clamp: log(0.1192/0.8808)
  double log_odds_max = 3.51154;     ///< upper clamp: log(0.971/0.029)
  double occupied_above = 0.0;       ///< log-odds above which a voxel is occupied (p > 0.5)

  /// Throws std::invalid_argument naming the first impossible value.
  void validate() const;
};

enum class VoxelState { kUnknown, kFree, kOccupied };

/// Bytes a map holds, split by whether another live map shares them.
struct OctreeMemory {
  std::size_t total_bytes = 0;   ///< every node reachable from this map
  std::size_t unique_bytes = 0;  ///< nodes only this map reaches (freed with it)
  std::size_t inner_nodes = 0;
  std::size_t bricks = 0;
  [[nodiscard]] std::size_t shared_bytes() const { return total_bytes - unique_bytes; }
};

class EvidenceOctree {
 public:
  explicit EvidenceOctree(const OctreeOptions& options = {});
  EvidenceOctree(const EvidenceOctree& other);
  EvidenceOctree& operator=(const EvidenceOctree& other);
  EvidenceOctree(EvidenceOctree&& other) noexcept;
  EvidenceOctree& operator=(EvidenceOctree&& other) noexcept;
  ~EvidenceOctree();

  [[nodiscard]] const OctreeOptions& options() const { return options_; }
  [[nodiscard]] const OctreeGrid& grid() const { return grid_; }

  // ---- reading ----
  /// Log-odds of a voxel; nullopt when it was never observed.
  [[nodiscard]] std::optional<float> log_odds(const OctreeKey& k) const;
  [[nodiscard]] VoxelState state(const OctreeKey& k) const;
  /// Occupancy probability, 0.5 for unknown voxels.
  [[nodiscard]] double probability(const OctreeKey& k) const;
  /// Calls f(key, log_odds) for every observed voxel, in key order of the tree.
  void for_each_voxel(const std::function<void(const OctreeKey&, float)>& f) const;
  [[nodiscard]] std::size_t known_voxels() const;
  /// Calls f(key, log_odds, base_log_odds) for every observed voxel of this map that lies in
  /// a brick this map does not share with `base` (base_log_odds: nullopt where `base` never
  /// observed the voxel). Subtrees both maps share are skipped without being visited, so for
  /// a copy of `base` the cost is that of what was written since the copy (SegSLAM merging).
  void for_each_voxel_not_shared_with(
      const EvidenceOctree& base, const std::function<void(const OctreeKey&, float, std::optional<float>)>& f) const;

  // ---- writing ----
  /// One observation of a voxel: adds the hit or miss log-odds and clamps.
  void update(const OctreeKey& k, bool hit);
  /// Sets a voxel's log-odds (clamped), e.g. when loading a map.
  void set_log_odds(const OctreeKey& k, float log_odds);

  // ---- sharing ----
  [[nodiscard]] OctreeMemory memory() const;
  /// Bytes held by a population of maps, each shared node counted once.
  static std::size_t distinct_bytes(const std::vector<const EvidenceOctree*>& maps);

 private:
  friend class OctreeReader;
  friend class OctreeWriter;

  OctreeOptions options_;
  OctreeGrid grid_;
  octree_detail::InnerNode* root_;
};

/// Fast repeated reads of one map: remembers the last brick and the last 32^3-voxel
/// subtree, so a query near the previous one descends 3 levels or none instead of 14.
/// Valid while the map is not written.
class OctreeReader {
 public:
  explicit OctreeReader(const EvidenceOctree& map) : map_(&map) {}
  /// Log-odds of a voxel; nullopt when unknown.
  std::optional<float> log_odds(int x, int y, int z);

 private:
  const octree_detail::Brick* brick_at(int x, int y, int z);

  const EvidenceOctree* map_;
  int cached_x_ = -1, cached_y_ = -1, cached_z_ = -1;
  const octree_detail::Brick* cached_ = nullptr;
  int anchor_x_ = -1, anchor_y_ = -1, anchor_z_ = -1;
  const octree_detail::InnerNode* anchor_ = nullptr;  // may be null: nothing known there
};

/// A batch of writes to one map: remembers the last brick it made private, so writes to
/// the same brick skip the copy-on-write descent. Do not copy the map during the batch.
class OctreeWriter {
 public:
  explicit OctreeWriter(EvidenceOctree& map);
  void update(const OctreeKey& k, bool hit);
  void set_log_odds(const OctreeKey& k, float log_odds);

 private:
  octree_detail::Brick& brick_at(const OctreeKey& k);

  EvidenceOctree* map_;
  float hit_, miss_, min_, max_;
  int cached_x_ = -1, cached_y_ = -1, cached_z_ = -1;
  octree_detail::Brick* cached_ = nullptr;
  int anchor_x_ = -1, anchor_y_ = -1, anchor_z_ = -1;
  octree_detail::InnerNode* anchor_ = nullptr;  // made private by this batch
};

}  // namespace lookahead::slam
