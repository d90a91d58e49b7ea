// SPDX-License-Identifier: MIT
#include "lookahead/exploration/breadcrumbs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace lookahead::exploration {

Breadcrumbs::Breadcrumbs(double spacing) : spacing_(spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("Breadcrumbs: spacing must be > 0");
}

void Breadcrumbs::drop(planner::Point2 p) {
  if (!crumbs_.empty() && std::hypot(p.x - crumbs_.back().x, p.y - crumbs_.back().y) < spacing_) return;
  crumbs_.push_back(p);
}

namespace {

// Crumbs bucketed on a grid of kLinkRadius cells: the crumbs within the radius of a point
// lie in its own bucket or the eight around it.
class CrumbBuckets {
 public:
  explicit CrumbBuckets(const std::vector<planner::Point2>& crumbs) : crumbs_(crumbs) {
    for (std::size_t i = 0; i < crumbs.size(); ++i) buckets_[key(crumbs[i])].push_back(i);
  }

  template <typename Visit>
  void near(planner::Point2 p, Visit&& visit) const {
    const auto [bx, by] = cell(p);
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = buckets_.find(pack(bx + dx, by + dy));
        if (it == buckets_.end()) continue;
        for (const std::size_t j : it->second) {
          const planner::Point2 q = crumbs_[j];
          if (std::hypot(q.x - p.x, q.y - p.y) <= Breadcrumbs::kLinkRadius) visit(j);
        }
      }
  }

 private:
  static std::pair<std::int64_t, std::int64_t> cell(planner::Point2 p) {
    return {static_cast<std::int64_t>(std::floor(p.x / Breadcrumbs::kLinkRadius)),
            static_cast<std::int64_t>(std::floor(p.y / Breadcrumbs::kLinkRadius))};
  }
  static std::int64_t pack(std::int64_t x, std::int64_t y) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(x) << 32) ^
                                     (static_cast<std::uint64_t>(y) & 0xffffffff));
  }
  static std::int64_t key(planner::Point2 p) {
    const auto [x, y] = cell(p);
    return pack(x, y);
  }

  const std::vector<planner::Point2>& crumbs_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> buckets_;
};

// The crumb the way starts from: the nearest one `passable` reaches from `from`, or the
// newest when none (or no `passable`).
std::size_t way_in(const std::vector<planner::Point2>& crumbs, const CrumbBuckets* buckets, planner::Point2 from,
                   const Breadcrumbs::Passable& passable) {
  std::size_t best = crumbs.size() - 1;
  if (!buckets) return best;
  double best_d = INFINITY;
  buckets->near(from, [&](std::size_t j) {
    const double d = planner::distance(crumbs[j], from);
    if (d < best_d && passable(from, crumbs[j])) {
      best_d = d;
      best = j;
    }
  });
  return best;
}

// Dijkstra over the crumbs: consecutive crumbs are joined (the robot drove between them),
// crumbs of different passes (found in `buckets`) where `passable` allows. Crumb indices
// from `from` to `to`.
std::vector<std::size_t> shortest_way(const std::vector<planner::Point2>& crumbs, const CrumbBuckets* buckets,
                                      std::size_t from, std::size_t to, const Breadcrumbs::Passable& passable) {
  const std::size_t n = crumbs.size();
  std::vector<double> dist(n, INFINITY);
  std::vector<std::size_t> parent(n, n);
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[from] = 0.0;
  open.push({0.0, from});
  const auto relax = [&](std::size_t i, std::size_t j) {
    const double d = dist[i] + planner::distance(crumbs[i], crumbs[j]);
    if (d >= dist[j]) return;
    dist[j] = d;
    parent[j] = i;
    open.push({d, j});
  };
  while (!open.empty()) {
    const double d = open.top().first;
    const std::size_t i = open.top().second;  // a plain variable: lambdas below capture it
    open.pop();
    if (i == to) break;
    if (d > dist[i]) continue;
    if (i > 0) relax(i, i - 1);
    if (i + 1 < n) relax(i, i + 1);
    if (!buckets) continue;
    buckets->near(crumbs[i], [&](std::size_t j) {
      if (j + 1 != i && j != i + 1 && j != i && dist[i] + planner::distance(crumbs[i], crumbs[j]) < dist[j] &&
          passable(crumbs[i], crumbs[j]))
        relax(i, j);
    });
  }
  std::vector<std::size_t> way;
  for (std::size_t i = to; i != n; i = parent[i]) way.push_back(i);
  std::reverse(way.begin(), way.end());
  return way;
}

}  // namespace

planner::Path Breadcrumbs::backtrack(planner::Point2 from, const std::function<bool(planner::Point2)>& outside,
                                     const Passable& passable) {
  std::size_t k = crumbs_.size();
  while (k > 0 && !outside(crumbs_[k - 1])) --k;
  if (k == 0) return {};
  const std::optional<CrumbBuckets> buckets = passable ? std::optional<CrumbBuckets>(crumbs_) : std::nullopt;
  const CrumbBuckets* b = buckets ? &*buckets : nullptr;
  planner::Path path{from};
  for (const std::size_t i : shortest_way(crumbs_, b, way_in(crumbs_, b, from, passable), k - 1, passable))
    path.push_back(crumbs_[i]);
  crumbs_.resize(k);  // the exit crumb stays: the trail goes on from there
  return path;
}

}  // namespace lookahead::exploration
