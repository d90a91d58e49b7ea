// SPDX-License-Identifier: MIT
#include "lookahead/exploration/predicted_map.hpp"

#include <array>
#include <cmath>
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

}  // namespace

void PredictedMap::add(const slam::HypothesisMap& h) {
  ++hypotheses_;
  slam::CellIndex lo, hi;
  if (!h.grid.known_bounds(lo, hi)) return;
  const auto psi = static_cast<float>(h.similarity);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const slam::CellIndex c{x, y};
      if (!h.grid.is_known(c) || confidence(c) > psi) continue;
      // Replace, not accumulate: the cell takes the better hypothesis' value.
      const int old = cells_.is_known(c) ? cells_.raw_log_odds(c) : 0;
      cells_.add_log_odds(c, h.grid.raw_log_odds(c) - old);
      confidence_[key(c)] = psi;
    }
  }
}

double PredictedMap::covered_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                   const SkipRule& rule) const {
  if (rule.variant == SkipVariant::kRegion && cluster.has_goal) {
    // Sec. II-B: the robot leaves out a region that is predicted. Its immediate far side
    // alone (predicted_share) says nothing of the unknown further on, which skipping
    // would leave neither explored nor predicted. A region no prediction touches is not
    // left out by one (RegionArea::covered): a frontier whose far side was seen since the
    // frontiers were last found has an empty region.
    return left_out(region_area(map, cluster, rule), rule) ? 1.0 : 0.0;
  }
  return predicted_share(map, cluster, rule.min_confidence);
}

RegionArea PredictedMap::region_area(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                     const SkipRule& rule) const {
  const double min_confidence = rule.min_confidence;
  const slam::CellIndex g = map.cell_at(cluster.goal_x, cluster.goal_y);
  const long r = std::lround(rule.region_radius / map.resolution());
  // A predicted wall closes the region as an explored one would (the predictor's
  // unexplored region stops at explored walls, predictor/src/unexplored_region.cpp).
  const int occupied = raw_at_least(rule.occupied);
  const auto wall = [&](slam::CellIndex c) {
    const int l = map.raw_log_odds(c);
    if (l != slam::GridTile::kUnknown) return l >= occupied;
    const int h = cells_.raw_log_odds(c);
    return h != slam::GridTile::kUnknown && h >= occupied && confidence(c) >= min_confidence;
  };
  // Beyond the paper: a wall seen from afar or at a grazing angle has unknown cells between
  // the beams' end points (1 deg at 8 m: 0.14 m apart); the region leaks through them to
  // the far side of the wall (beyond the outer wall: unknown for good, never predicted), and
  // the frontier is never left out. A gap no wider than wall_gap (the maze study: the
  // robot's diameter, no way for it) counts as wall. README, P-SLAM 1.
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
      // what the robot has seen (slivers that counted such gaps left two maze runs at 93-94 %
      // explored or predicted; README, P-SLAM 1).
      if (rule.skip_wall_slivers && inside(c) && !wall(c) && !in_gap_of(c, explored_wall)) gap_of_prediction = true;
    }
  };
  const auto neighbours = [](slam::CellIndex c) {
    return std::array<slam::CellIndex, 4>{{{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}}};
  };
  for (const slam::CellIndex c : cluster.cells)
    for (const slam::CellIndex n : neighbours(c)) push(n);
  std::size_t unpredicted = 0, predicted = 0;
  while (!open.empty()) {
    const slam::CellIndex c = open.front();
    open.pop_front();
    const bool known = cells_.is_known(c) && confidence(c) >= min_confidence;
    unpredicted += !known;
    predicted += known;
    for (const slam::CellIndex n : neighbours(c)) push(n);
  }
  const double cell = map.resolution() * map.resolution();
  return {static_cast<double>(predicted) * cell, static_cast<double>(unpredicted) * cell, closed_by_prediction,
          closed_by_gap, gap_of_prediction};
}

double PredictedMap::confidence(slam::CellIndex c) const {
  const auto it = confidence_.find(key(c));
  return it == confidence_.end() ? 0.0 : static_cast<double>(it->second);
}

double PredictedMap::predicted_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                     double min_confidence) const {
  std::size_t unknown = 0, covered = 0;
  for (const slam::CellIndex c : cluster.cells) {
    for (const slam::CellIndex n : {slam::CellIndex{c.x + 1, c.y}, slam::CellIndex{c.x - 1, c.y},
                                    slam::CellIndex{c.x, c.y + 1}, slam::CellIndex{c.x, c.y - 1}}) {
      if (map.is_known(n)) continue;
      ++unknown;
      covered += predicted(map, n) && confidence(n) >= min_confidence;
    }
  }
  return unknown > 0 ? static_cast<double>(covered) / static_cast<double>(unknown) : 0.0;
}

}  // namespace lookahead::exploration
