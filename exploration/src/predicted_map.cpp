// SPDX-License-Identifier: MIT
#include "lookahead/exploration/predicted_map.hpp"

#include <cmath>

#include "lookahead/exploration/region_flood.hpp"

namespace lookahead::exploration {

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
    return left_out(flood_region(map, *this, cluster, rule, rule.region_tolerance), rule) ? 1.0 : 0.0;
  }
  return predicted_share(map, cluster, rule.min_confidence);
}

RegionArea PredictedMap::region_area(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                     const SkipRule& rule) const {
  return flood_region(map, *this, cluster, rule);
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
