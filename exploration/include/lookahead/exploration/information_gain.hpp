// SPDX-License-Identifier: MIT
// Expected information of a goal: the unknown area a 360-degree sensor of the given range
// could see from it (Gonzalez-Banos & Latombe 2002, sec. 4: the area of the unknown region
// visible from a candidate; it ranks frontiers, it does not predict the scan).
#pragma once

#include <functional>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

/// Cells a caller treats as known besides the map's (the P-SLAM strategy passes its
/// predicted cells); null = none.
using CountsAsKnown = std::function<bool(slam::CellIndex)>;

/// Cells a caller treats as walls besides the map's (predicted walls); null = none.
using Occludes = std::function<bool(slam::CellIndex)>;
/// Unknown area [m^2] in line of sight within `range` of (x, y): rays fan out from the goal
/// and stop at the map's occupied cells (and at cells `occludes` names); unknown cells are
/// taken to be transparent (the optimistic assumption of Gonzalez-Banos & Latombe). Space
/// behind a wall already mapped, such as the outside of the building, does not count.
double visible_information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                                const CountsAsKnown& counts_as_known = nullptr, const Occludes& occludes = nullptr);

/// Unknown area [m^2] within `range` of (x, y), walls ignored (the disc approximation: an
/// upper bound of the gain above, for tests and benchmarks).
double information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                        const CountsAsKnown& counts_as_known = nullptr);

}  // namespace lookahead::exploration
