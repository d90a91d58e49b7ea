// SPDX-License-Identifier: MIT
#include "lookahead/exploration/travel_cost.hpp"

#include <algorithm>
#include <cmath>
#include <queue>

namespace lookahead::exploration {

using slam::CellIndex;

TravelCost::TravelCost(CellIndex lo, CellIndex hi, double resolution, CellIndex start,
                       const std::function<bool(CellIndex)>& traversable)
    : lo_(lo), hi_(hi), width_(hi.x - lo.x + 1), height_(hi.y - lo.y + 1) {
  if (width_ <= 0 || height_ <= 0) return;
  dist_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_),
               std::numeric_limits<float>::infinity());
  parent_.assign(dist_.size(), -1);
  const int s = index(start);
  if (s < 0 || !traversable(start)) return;
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist_[static_cast<std::size_t>(s)] = 0.0f;
  open.push({0.0f, s});
  const float straight = static_cast<float>(resolution);
  const float diagonal = static_cast<float>(resolution * std::sqrt(2.0));
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist_[static_cast<std::size_t>(i)]) continue;  // a stale queue entry
    const CellIndex c{lo_.x + i % width_, lo_.y + i / width_};
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const CellIndex n{c.x + dx, c.y + dy};
        const int j = index(n);
        if (j < 0) continue;
        const bool diag = dx != 0 && dy != 0;
        const float nd = d + (diag ? diagonal : straight);
        if (nd >= dist_[static_cast<std::size_t>(j)] || !traversable(n)) continue;
        // No corner cutting: the planner's segment check refuses a diagonal squeeze between
        // two blocked cells, so the price must not count it as a way through either.
        if (diag && (!traversable({c.x + dx, c.y}) || !traversable({c.x, c.y + dy}))) continue;
        {
          parent_[static_cast<std::size_t>(j)] = i;
          dist_[static_cast<std::size_t>(j)] = nd;
          open.push({nd, j});
        }
      }
    }
  }
}

std::vector<CellIndex> TravelCost::path_to(CellIndex c) const {
  std::vector<CellIndex> path;
  if (!reachable(c)) return path;
  for (int i = index(c); i >= 0; i = parent_[static_cast<std::size_t>(i)]) {
    path.push_back({lo_.x + i % width_, lo_.y + i / width_});
  }
  std::reverse(path.begin(), path.end());
  return path;
}

int TravelCost::index(CellIndex c) const {
  if (c.x < lo_.x || c.y < lo_.y || c.x > hi_.x || c.y > hi_.y) return -1;
  return (c.y - lo_.y) * width_ + (c.x - lo_.x);
}

double TravelCost::at(CellIndex c) const {
  const int i = index(c);
  return i < 0 || dist_.empty() ? kInfinity : static_cast<double>(dist_[static_cast<std::size_t>(i)]);
}

}  // namespace lookahead::exploration
