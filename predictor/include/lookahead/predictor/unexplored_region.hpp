// SPDX-License-Identifier: MIT
// The unexplored region beyond a target frontier f (Chang et al. 2007, sec. III-C: "the
// unexplored parts in the target region"), which a hypothesis covers.
#pragma once

#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::predictor {

/// Every unknown cell within this of f seeds the region [m]: the goal stands on free space
/// near the frontier, not on it.
constexpr double kSeedRadius = 1.0;

/// Unknown cells within diameter d of f reachable from the seeds through unknown cells.
/// Our reading: unknown cells sealed off by explored walls (inside a pillar, far behind an
/// outer wall) are not beyond this frontier, and a hypothesis there could never be checked
/// by going to the target. Seeds behind a wall within kSeedRadius of f do count (see the
/// .cpp for why).
std::vector<slam::CellIndex> unexplored_region(const slam::OccupancyGrid& map, double tx, double ty, double diameter);

}  // namespace lookahead::predictor
