// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/evidence_octree.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace lookahead::slam {

using octree_detail::Brick;
using octree_detail::InnerNode;
using octree_detail::kInnerLevels;
using octree_detail::NodeBase;

namespace {

bool shared(const NodeBase* n) { return n->refs.load(std::memory_order_acquire) != 1; }

/// Makes `slot` (a node at `level`) private to the caller: copies it when shared.
template <typename Node>
Node* make_private(NodeBase*& slot, int level) {
  if (!slot) {
    slot = new Node;
  } else if (shared(slot)) {
    Node* copy = octree_detail::clone(*static_cast<const Node*>(slot));
    octree_detail::release(slot, level);
    slot = copy;
  }
  return static_cast<Node*>(slot);
}

/// The node at `to_level` on the path to (x, y, z), starting from `node` at `from_level`;
/// null where the path ends early (nothing observed there).
const NodeBase* descend(const NodeBase* node, int from_level, int to_level, int x, int y, int z) {
  for (int level = from_level; level < to_level && node; ++level) {
    node = static_cast<const InnerNode*>(node)->child[octree_detail::child_index(x, y, z, level)];
  }
  return node;
}

template <typename Visit>
void walk(const NodeBase* n, int level, int x, int y, int z, const Visit& visit) {
  if (!visit(n, level, x, y, z)) return;
  if (level == kInnerLevels) return;
  const int bit = 15 - level;
  const auto* inner = static_cast<const InnerNode*>(n);
  for (int i = 0; i < 8; ++i) {
    if (!inner->child[i]) continue;
    walk(inner->child[i], level + 1, x | ((i & 1) << bit), y | (((i >> 1) & 1) << bit), z | (((i >> 2) & 1) << bit),
         visit);
  }
}

// Walks `n` and, in step, the node `base` at the same place of another map (null where that
// map holds nothing), skipping every node the two share; calls visit(brick, base brick, x, y,
// z) for the bricks they do not.
template <typename Visit>
void walk_unshared(const NodeBase* n, const NodeBase* base, int level, int x, int y, int z, const Visit& visit) {
  if (!n || n == base) return;
  if (level == kInnerLevels) {
    visit(static_cast<const Brick*>(n), static_cast<const Brick*>(base), x, y, z);
    return;
  }
  const int bit = 15 - level;
  const auto* inner = static_cast<const InnerNode*>(n);
  const auto* other = static_cast<const InnerNode*>(base);
  for (int i = 0; i < 8; ++i) {
    walk_unshared(inner->child[i], other ? other->child[i] : nullptr, level + 1, x | ((i & 1) << bit),
                  y | (((i >> 1) & 1) << bit), z | (((i >> 2) & 1) << bit), visit);
  }
}

std::size_t node_bytes(int level) { return level == kInnerLevels ? sizeof(Brick) : sizeof(InnerNode); }

}  // namespace

void OctreeOptions::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("octree: ") + what);
  };
  require(resolution >= 0.001 && resolution <= 100.0, "resolution must be in [0.001, 100] m");
  require(log_odds_hit > 0.0, "log_odds_hit must be > 0");
  require(log_odds_miss < 0.0, "log_odds_miss must be < 0");
  require(log_odds_min < log_odds_max, "log_odds_min must be < log_odds_max");
  require(occupied_above > log_odds_min && occupied_above < log_odds_max, "occupied_above must lie between the clamps");
}

EvidenceOctree::EvidenceOctree(const OctreeOptions& options)
    : options_(options), grid_(options.resolution), root_(new InnerNode) {
  options_.validate();
}

EvidenceOctree::EvidenceOctree(const EvidenceOctree& other)
    : options_(other.options_), grid_(other.grid_), root_(other.root_) {
  octree_detail::retain(root_);
}

EvidenceOctree& EvidenceOctree::operator=(const EvidenceOctree& other) {
  if (this == &other) return *this;
  octree_detail::retain(other.root_);
  octree_detail::release(root_, 0);
  options_ = other.options_;
  grid_ = other.grid_;
  root_ = other.root_;
  return *this;
}

EvidenceOctree::EvidenceOctree(EvidenceOctree&& other) noexcept
    : options_(other.options_), grid_(other.grid_), root_(other.root_) {
  other.root_ = nullptr;
}

EvidenceOctree& EvidenceOctree::operator=(EvidenceOctree&& other) noexcept {
  std::swap(options_, other.options_);
  std::swap(grid_, other.grid_);
  std::swap(root_, other.root_);
  return *this;
}

EvidenceOctree::~EvidenceOctree() {
  if (root_) octree_detail::release(root_, 0);
}

std::optional<float> EvidenceOctree::log_odds(const OctreeKey& k) const {
  return OctreeReader(*this).log_odds(k.x, k.y, k.z);
}

VoxelState EvidenceOctree::state(const OctreeKey& k) const {
  const std::optional<float> l = log_odds(k);
  if (!l) return VoxelState::kUnknown;
  return *l > options_.occupied_above ? VoxelState::kOccupied : VoxelState::kFree;
}

double EvidenceOctree::probability(const OctreeKey& k) const {
  const std::optional<float> l = log_odds(k);
  return l ? 1.0 - 1.0 / (1.0 + std::exp(static_cast<double>(*l))) : 0.5;
}

void EvidenceOctree::for_each_voxel(const std::function<void(const OctreeKey&, float)>& f) const {
  walk(root_, 0, 0, 0, 0, [&](const NodeBase* n, int level, int x, int y, int z) {
    if (level < kInnerLevels) return true;
    const auto* b = static_cast<const Brick*>(n);
    for (int v = 0; v < octree_detail::kBrickVoxels; ++v) {
      if (!((b->known >> v) & 1U)) continue;
      const OctreeKey k{static_cast<std::uint16_t>(x | (v & 3)), static_cast<std::uint16_t>(y | ((v >> 2) & 3)),
                        static_cast<std::uint16_t>(z | ((v >> 4) & 3))};
      f(k, b->log_odds[static_cast<std::size_t>(v)]);
    }
    return false;
  });
}

std::size_t EvidenceOctree::known_voxels() const {
  std::size_t n = 0;
  walk(root_, 0, 0, 0, 0, [&](const NodeBase* node, int level, int, int, int) {
    if (level == kInnerLevels)
      n += static_cast<std::size_t>(__builtin_popcountll(static_cast<const Brick*>(node)->known));
    return true;
  });
  return n;
}

void EvidenceOctree::for_each_voxel_not_shared_with(
    const EvidenceOctree& base, const std::function<void(const OctreeKey&, float, std::optional<float>)>& f) const {
  walk_unshared(root_, base.root_, 0, 0, 0, 0, [&](const Brick* b, const Brick* other, int x, int y, int z) {
    for (int v = 0; v < octree_detail::kBrickVoxels; ++v) {
      if (!((b->known >> v) & 1U)) continue;
      const OctreeKey k{static_cast<std::uint16_t>(x | (v & 3)), static_cast<std::uint16_t>(y | ((v >> 2) & 3)),
                        static_cast<std::uint16_t>(z | ((v >> 4) & 3))};
      const auto i = static_cast<std::size_t>(v);
      f(k, b->log_odds[i],
        other && ((other->known >> v) & 1U) ? std::optional<float>(other->log_odds[i]) : std::nullopt);
    }
  });
}

void EvidenceOctree::update(const OctreeKey& k, bool hit) { OctreeWriter(*this).update(k, hit); }

void EvidenceOctree::set_log_odds(const OctreeKey& k, float log_odds) { OctreeWriter(*this).set_log_odds(k, log_odds); }

OctreeMemory EvidenceOctree::memory() const {
  OctreeMemory m;
  walk(root_, 0, 0, 0, 0, [&](const NodeBase*, int level, int, int, int) {
    m.total_bytes += node_bytes(level);
    (level == kInnerLevels ? m.bricks : m.inner_nodes) += 1;
    return true;
  });
  // A node is unique to this map when every node on its path, itself included, has one
  // parent: below a shared node everything is reachable from the other owners too.
  walk(root_, 0, 0, 0, 0, [&](const NodeBase* n, int level, int, int, int) {
    if (shared(n)) return false;
    m.unique_bytes += node_bytes(level);
    return true;
  });
  return m;
}

std::size_t EvidenceOctree::distinct_bytes(const std::vector<const EvidenceOctree*>& maps) {
  std::unordered_set<const NodeBase*> seen;
  std::size_t bytes = 0;
  for (const EvidenceOctree* map : maps) {
    walk(map->root_, 0, 0, 0, 0, [&](const NodeBase* n, int level, int, int, int) {
      if (!seen.insert(n).second) return false;  // counted, with its subtree, already
      bytes += node_bytes(level);
      return true;
    });
  }
  return bytes;
}

// ---- OctreeReader ----

const Brick* OctreeReader::brick_at(int x, int y, int z) {
  const int bx = x >> octree_detail::kBrickBits, by = y >> octree_detail::kBrickBits,
            bz = z >> octree_detail::kBrickBits;
  if (bx == cached_x_ && by == cached_y_ && bz == cached_z_) return cached_;
  const int ax = x >> octree_detail::kAnchorShift, ay = y >> octree_detail::kAnchorShift,
            az = z >> octree_detail::kAnchorShift;
  if (ax != anchor_x_ || ay != anchor_y_ || az != anchor_z_) {
    anchor_ = static_cast<const InnerNode*>(descend(map_->root_, 0, octree_detail::kAnchorLevel, x, y, z));
    anchor_x_ = ax, anchor_y_ = ay, anchor_z_ = az;
  }
  cached_ = static_cast<const Brick*>(descend(anchor_, octree_detail::kAnchorLevel, kInnerLevels, x, y, z));
  cached_x_ = bx, cached_y_ = by, cached_z_ = bz;
  return cached_;
}

std::optional<float> OctreeReader::log_odds(int x, int y, int z) {
  if (static_cast<unsigned>(x | y | z) >= (1U << OctreeGrid::kKeyBits)) return std::nullopt;
  const Brick* b = brick_at(x, y, z);
  if (!b) return std::nullopt;
  const int v = octree_detail::voxel_index(x, y, z);
  if (!((b->known >> v) & 1U)) return std::nullopt;
  return b->log_odds[static_cast<std::size_t>(v)];
}

// ---- OctreeWriter ----

OctreeWriter::OctreeWriter(EvidenceOctree& map)
    : map_(&map),
      hit_(static_cast<float>(map.options_.log_odds_hit)),
      miss_(static_cast<float>(map.options_.log_odds_miss)),
      min_(static_cast<float>(map.options_.log_odds_min)),
      max_(static_cast<float>(map.options_.log_odds_max)) {}

Brick& OctreeWriter::brick_at(const OctreeKey& k) {
  const int bx = k.x >> octree_detail::kBrickBits, by = k.y >> octree_detail::kBrickBits,
            bz = k.z >> octree_detail::kBrickBits;
  if (cached_ && bx == cached_x_ && by == cached_y_ && bz == cached_z_) return *cached_;
  const int ax = k.x >> octree_detail::kAnchorShift, ay = k.y >> octree_detail::kAnchorShift,
            az = k.z >> octree_detail::kAnchorShift;
  if (!anchor_ || ax != anchor_x_ || ay != anchor_y_ || az != anchor_z_) {
    NodeBase* root = map_->root_;
    InnerNode* node = make_private<InnerNode>(root, 0);
    map_->root_ = node;
    for (int level = 0; level < octree_detail::kAnchorLevel; ++level) {
      node = make_private<InnerNode>(node->child[octree_detail::child_index(k.x, k.y, k.z, level)], level + 1);
    }
    anchor_ = node;
    anchor_x_ = ax, anchor_y_ = ay, anchor_z_ = az;
  }
  InnerNode* node = anchor_;
  for (int level = octree_detail::kAnchorLevel; level + 1 < kInnerLevels; ++level) {
    node = make_private<InnerNode>(node->child[octree_detail::child_index(k.x, k.y, k.z, level)], level + 1);
  }
  cached_ = make_private<Brick>(node->child[octree_detail::child_index(k.x, k.y, k.z, kInnerLevels - 1)], kInnerLevels);
  cached_x_ = bx, cached_y_ = by, cached_z_ = bz;
  return *cached_;
}

void OctreeWriter::update(const OctreeKey& k, bool hit) {
  Brick& b = brick_at(k);
  const int v = octree_detail::voxel_index(k.x, k.y, k.z);
  const std::uint64_t bit = std::uint64_t{1} << v;
  float& l = b.log_odds[static_cast<std::size_t>(v)];
  if (!(b.known & bit)) {
    b.known |= bit;
    l = 0.0f;  // a new voxel starts at p = 0.5, as in OctoMap
  }
  l = std::clamp(l + (hit ? hit_ : miss_), min_, max_);
}

void OctreeWriter::set_log_odds(const OctreeKey& k, float log_odds) {
  Brick& b = brick_at(k);
  const int v = octree_detail::voxel_index(k.x, k.y, k.z);
  b.known |= std::uint64_t{1} << v;
  b.log_odds[static_cast<std::size_t>(v)] = std::clamp(log_odds, min_, max_);
}

}  // namespace lookahead::slam
