// SPDX-License-Identifier: MIT
// The unexplored region beyond a target frontier f (Chang et al. 2007, sec. III-C: "the
// unexplored parts in the target region"), which a hypothesis covers.
#pragma once

#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::predictor {

/// Seeds: unknown cells within this of f that f reaches without crossing a wall [m].
constexpr double kSeedRadius = 1.0;
/// Unknown passages narrower than this do not join the region [m]: the narrowest doors of
/// our worlds are 0.6 m, so a gap this narrow in a mapped wall is beams that missed it.
constexpr double kMinOpening = 0.3;

/// Unknown cells within diameter d of f reachable from it through unknown cells, the
/// passages at least `min_opening` wide. Our reading: unknown cells sealed off by explored
/// walls (behind an outer wall, inside a pillar) are not beyond this frontier, and a
/// hypothesis there could never be checked by going to the target.
std::vector<slam::CellIndex> unexplored_region(const slam::OccupancyGrid& map, double tx, double ty, double diameter,
                                               double min_opening = kMinOpening);

}  // namespace lookahead::predictor
