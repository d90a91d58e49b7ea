// SPDX-License-Identifier: MIT
// Expected information of a goal: the unknown area a sensor of the given range could see
// from it (the disc approximation of Gonzalez-Banos & Latombe 2002, without occlusion: it
// ranks frontiers, it does not predict the scan).
#pragma once

#include <functional>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

/// Unknown area [m^2] within `range` of (x, y). `counts_as_known` lets a caller treat more
/// cells as known (the P-SLAM strategy passes its predicted cells); null = none.
double information_gain(const slam::OccupancyGrid& grid, double x, double y, double range,
                        const std::function<bool(slam::CellIndex)>& counts_as_known = nullptr);

}  // namespace lookahead::exploration
