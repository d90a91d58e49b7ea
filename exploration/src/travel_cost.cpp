// SPDX-License-Identifier: MIT
#include "lookahead/exploration/travel_cost.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <queue>

namespace lookahead::exploration {

using slam::CellIndex;

TravelCost::TravelCost(CellIndex lo, CellIndex hi, double resolution, CellIndex start,
                       const std::function<bool(CellIndex)>& traversable, const std::vector<CellIndex>& targets)
    : lo_(lo), hi_(hi), width_(hi.x - lo.x + 1), height_(hi.y - lo.y + 1) {
  if (width_ <= 0 || height_ <= 0) return;
  const std::size_t n = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  dist_.assign(n, std::numeric_limits<float>::infinity());
  parent_.assign(n, -1);
  // Each cell is asked once (a cell is a neighbour, or beside a diagonal step, of up to 12).
  enum : std::uint8_t { kUnasked, kBlocked, kOpen };
  std::vector<std::uint8_t> state(n, kUnasked);
  const auto open_cell = [&](CellIndex c, int j) {
    std::uint8_t& st = state[static_cast<std::size_t>(j)];
    if (st == kUnasked) st = traversable(c) ? kOpen : kBlocked;
    return st == kOpen;
  };
  const int s = index(start);
  if (s < 0 || !open_cell(start, s)) return;
  std::vector<std::uint8_t> is_target;
  std::size_t pending = 0;
  if (!targets.empty()) {
    is_target.assign(n, 0);
    for (const CellIndex t : targets) {
      const int j = index(t);
      if (j >= 0 && !is_target[static_cast<std::size_t>(j)]) {
        is_target[static_cast<std::size_t>(j)] = 1;
        ++pending;
      }
    }
    if (pending == 0) pending = n + 1;  // no target inside: the whole search
  }
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
    if (!is_target.empty() && is_target[static_cast<std::size_t>(i)] && --pending == 0) break;
    const CellIndex c{lo_.x + i % width_, lo_.y + i / width_};
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const CellIndex nb{c.x + dx, c.y + dy};
        const int j = index(nb);
        if (j < 0) continue;
        const bool diag = dx != 0 && dy != 0;
        const float nd = d + (diag ? diagonal : straight);
        if (nd >= dist_[static_cast<std::size_t>(j)] || !open_cell(nb, j)) continue;
        // No corner cutting: the planner's segment check refuses a diagonal squeeze between
        // two blocked cells, so the price must not count it as a way through either.
        if (diag && (!open_cell({c.x + dx, c.y}, i + dx) || !open_cell({c.x, c.y + dy}, i + dy * width_))) continue;
        parent_[static_cast<std::size_t>(j)] = i;
        dist_[static_cast<std::size_t>(j)] = nd;
        open.push({nd, j});
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
