// SPDX-License-Identifier: MIT
#include "lookahead/exploration/goal_blacklist.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {

bool GoalBlacklist::add(double x, double y, double now) {
  auto spot = std::find_if(spots_.begin(), spots_.end(),
                           [&](const Spot& s) { return std::hypot(s.x - x, s.y - y) <= options_.radius; });
  if (spot == spots_.end()) spot = spots_.insert(spots_.end(), {x, y, 0});
  const bool for_good = ++spot->strikes >= options_.max_strikes;
  entries_.push_back({x, y, for_good ? INFINITY : now + options_.lifetime});
  return for_good;
}

bool GoalBlacklist::permanent(double x, double y) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return std::isinf(e.expires) && std::hypot(e.x - x, e.y - y) <= options_.radius;
  });
}

bool GoalBlacklist::contains(double x, double y, double now) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) {
    return e.expires > now && std::hypot(e.x - x, e.y - y) <= options_.radius;
  });
}

std::size_t GoalBlacklist::forgive_permanent() {
  std::size_t forgiven = 0;
  for (Spot& spot : spots_) {
    if (spot.strikes < options_.max_strikes) continue;
    spot.strikes = 0;
    ++forgiven;
  }
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [](const Entry& e) { return std::isinf(e.expires); }),
                 entries_.end());
  return forgiven;
}

std::size_t GoalBlacklist::expire(double now) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.expires <= now; }),
                 entries_.end());
  return entries_.size();
}

}  // namespace lookahead::exploration
