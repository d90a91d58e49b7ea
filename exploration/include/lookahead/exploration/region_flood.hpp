// SPDX-License-Identifier: MIT
// The region flood behind the look-ahead skip rule `lookahead.skip: region` (P-SLAM sec.
// II-B, skip_rule.hpp): a frontier's unexplored region is the unknown cells within
// rule.region_radius of its goal reachable from its far side (4-connected) through unknown
// cells, not through walls, explored or predicted (probability >= rule.occupied, predicted
// by a hypothesis with Psi >= rule.min_confidence). Unknown gaps up to rule.wall_gap wide
// in a wall close it as the wall would, and nothing beyond rule.boundary belongs to it. The
// region is split into the part a hypothesis predicts and the part driving there would
// still reveal.
#pragma once

#include <limits>

#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/skip_rule.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

/// The unexplored region beyond `cluster` in `map`, with what `look_ahead` covers of it.
/// The flood stops once more than `stop_above_unpredicted` [m^2] of it is unpredicted: a
/// region that large is left out by no rule (left_out()), and most frontiers' regions are,
/// so deciding needs a few hundred cells where the whole region holds tens of thousands.
[[nodiscard]] RegionArea flood_region(const slam::OccupancyGrid& map, const PredictedMap& look_ahead,
                                      const FrontierCluster& cluster, const SkipRule& rule,
                                      double stop_above_unpredicted = std::numeric_limits<double>::infinity());

}  // namespace lookahead::exploration
