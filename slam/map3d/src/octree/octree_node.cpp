// SPDX-License-Identifier: MIT
#include "lookahead/slam/octree/octree_node.hpp"

#include <vector>

namespace lookahead::slam::octree_detail {

void release(const NodeBase* n, int level) {
  // Iterative, with an explicit stack: a map is 15 levels deep, but freeing a whole map
  // recursively from a worker thread costs stack for no reason.
  std::vector<std::pair<const NodeBase*, int>> pending;
  if (n) pending.emplace_back(n, level);
  while (!pending.empty()) {
    const auto [node, lvl] = pending.back();
    pending.pop_back();
    if (node->refs.fetch_sub(1, std::memory_order_acq_rel) != 1) continue;
    if (lvl == kInnerLevels) {
      delete static_cast<const Brick*>(node);
      continue;
    }
    const auto* inner = static_cast<const InnerNode*>(node);
    for (const NodeBase* c : inner->child) {
      if (c) pending.emplace_back(c, lvl + 1);
    }
    delete inner;
  }
}

InnerNode* clone(const InnerNode& n) {
  auto* copy = new InnerNode;
  copy->child = n.child;
  for (const NodeBase* c : copy->child) retain(c);
  return copy;
}

Brick* clone(const Brick& b) {
  auto* copy = new Brick;
  copy->known = b.known;
  copy->log_odds = b.log_odds;
  return copy;
}

}  // namespace lookahead::slam::octree_detail
