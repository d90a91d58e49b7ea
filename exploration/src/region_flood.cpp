// SPDX-License-Identifier: MIT
#include "lookahead/exploration/region_flood.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <unordered_set>

namespace lookahead::exploration {

namespace {

// The smallest raw log-odds whose probability (OccupancyGrid::probability, the same formula)
// is at least `p`: the flood tests walls by one integer compare instead of an exp per cell.
int raw_at_least(double p) {
  int lo = slam::GridTile::kUnknown + 1, hi = std::numeric_limits<std::int16_t>::max();
  const auto passes = [&](int l) {
    return 1.0 / (1.0 + std::exp(-static_cast<double>(l) / slam::GridTile::kLogOddsScale)) >= p;
  };
  if (!passes(hi)) return hi + 1;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (passes(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

std::int64_t key(slam::CellIndex c) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) << 32) |
                                   static_cast<std::uint32_t>(c.y));
}

}  // namespace

RegionArea flood_region(const slam::OccupancyGrid& map, const PredictedMap& look_ahead, const FrontierCluster& cluster,
                        const SkipRule& rule, double stop_above_unpredicted) {
  const slam::OccupancyGrid& cells = look_ahead.cells();
  const double min_confidence = rule.min_confidence;
  const slam::CellIndex g = map.cell_at(cluster.goal_x, cluster.goal_y);
  const long r = std::lround(rule.region_radius / map.resolution());
  // A predicted wall closes the region as an explored one would (the predictor's
  // unexplored region stops at explored walls, predictor/src/unexplored_region.cpp).
  const int occupied = raw_at_least(rule.occupied);
  const auto wall = [&](slam::CellIndex c) {
    const int l = map.raw_log_odds(c);
    if (l != slam::GridTile::kUnknown) return l >= occupied;
    const int h = cells.raw_log_odds(c);
    return h != slam::GridTile::kUnknown && h >= occupied && look_ahead.confidence(c) >= min_confidence;
  };
  // Beyond the paper: a wall seen from afar or at a grazing angle has unknown cells between
  // the beams' end points (1 deg at 8 m: 0.14 m apart); the region leaks through them to
  // the far side of the wall (beyond the outer wall: unknown for good, never predicted), and
  // the frontier is never left out. A gap no wider than wall_gap (the mission sets at most
  // the robot's diameter: no way for it) counts as wall.
  const int gap = static_cast<int>(std::lround(rule.wall_gap / 2 / map.resolution()));
  const auto in_gap_of = [&](slam::CellIndex c, const auto& is_wall) {
    for (int dy = -gap; dy <= gap; ++dy)
      for (int dx = -gap; dx <= gap; ++dx)
        if (dx * dx + dy * dy <= gap * gap && (dx != 0 || dy != 0) && is_wall(slam::CellIndex{c.x + dx, c.y + dy}))
          return true;
    return false;
  };
  const auto in_gap = [&](slam::CellIndex c) { return in_gap_of(c, wall); };
  const auto explored_wall = [&](slam::CellIndex c) { return map.raw_log_odds(c) >= occupied; };
  const auto inside = [&](slam::CellIndex c) {
    if (!rule.boundary) return true;
    double x, y;
    map.cell_center(c, x, y);
    return x >= rule.boundary->min_x && x <= rule.boundary->max_x && y >= rule.boundary->min_y &&
           y <= rule.boundary->max_y;
  };
  // Unexplored: never seen, and with the sliver rule also seen but undecided, as the frontier
  // detector counts it (a band of such cells alone makes a frontier).
  const int free_from = rule.skip_wall_slivers ? raw_at_least(rule.free) : occupied;
  const auto unexplored = [&](slam::CellIndex c) {
    const int l = map.raw_log_odds(c);
    return l == slam::GridTile::kUnknown || (l >= free_from && l < occupied);
  };
  const auto walkable = [&](slam::CellIndex c) {
    const long dx = c.x - g.x, dy = c.y - g.y;
    if (dx * dx + dy * dy > r * r || !unexplored(c) || wall(c) || !inside(c)) return false;
    return gap == 0 || !in_gap(c);
  };
  std::unordered_set<std::int64_t> seen;
  std::deque<slam::CellIndex> open;
  bool closed_by_prediction = false, closed_by_gap = false, gap_of_prediction = false;
  const auto push = [&](slam::CellIndex c) {
    if (walkable(c)) {
      if (seen.insert(key(c)).second) open.push_back(c);
    } else if (!map.is_known(c) && wall(c)) {
      closed_by_prediction = true;  // an unknown cell that is a wall: a predicted one
    } else if (unexplored(c)) {
      const long dx = c.x - g.x, dy = c.y - g.y;
      if (dx * dx + dy * dy > r * r) return;
      closed_by_gap = true;  // within the radius: a gap, or the boundary
      // A gap that only a predicted wall makes is the prediction's: a wall sliver is closed by
      // what the robot has seen. Counting such gaps for slivers would skip, unobserved,
      // pockets whose only closure is a guess.
      if (rule.skip_wall_slivers && inside(c) && !wall(c) && !in_gap_of(c, explored_wall)) gap_of_prediction = true;
    }
  };
  const auto neighbours = [](slam::CellIndex c) {
    return std::array<slam::CellIndex, 4>{{{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}}};
  };
  for (const slam::CellIndex c : cluster.cells)
    for (const slam::CellIndex n : neighbours(c)) push(n);
  std::size_t unpredicted = 0, predicted = 0;
  const double cell = map.resolution() * map.resolution();
  while (!open.empty() && static_cast<double>(unpredicted) * cell <= stop_above_unpredicted) {
    const slam::CellIndex c = open.front();
    open.pop_front();
    const bool known = cells.is_known(c) && look_ahead.confidence(c) >= min_confidence;
    unpredicted += !known;
    predicted += known;
    for (const slam::CellIndex n : neighbours(c)) push(n);
  }
  return {static_cast<double>(predicted) * cell, static_cast<double>(unpredicted) * cell, closed_by_prediction,
          closed_by_gap, gap_of_prediction};
}

}  // namespace lookahead::exploration
