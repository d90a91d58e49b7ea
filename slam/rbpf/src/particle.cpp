// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/particle.hpp"

namespace lookahead::slam {

TrajectoryNode::~TrajectoryNode() {
  std::shared_ptr<const TrajectoryNode> next = std::move(parent);
  // While we hold the last reference to the next node, detach its parent before letting it go.
  while (next && next.use_count() == 1) {
    auto up = std::move(const_cast<TrajectoryNode&>(*next).parent);
    next = std::move(up);
  }
}

}  // namespace lookahead::slam
