// SPDX-License-Identifier: MIT
#include "lookahead/exploration/goal_blacklist.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {

bool GoalBlacklist::contains(double x, double y, double now) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return e.expires > now && std::hypot(e.x - x, e.y - y) <= options_.radius;
  });
}

std::size_t GoalBlacklist::expire(double now) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.expires <= now; }),
                 entries_.end());
  return entries_.size();
}

}  // namespace lookahead::exploration
