// SPDX-License-Identifier: MIT
// Exact squared Euclidean distance transform of a binary raster: Felzenszwalb & Huttenlocher,
// "Distance Transforms of Sampled Functions", Theory of Computing 8 (2012), Sec. 2.1 (lower
// envelope of parabolas), applied to the columns and then to the rows. O(cells).
#pragma once

#include <cstdint>
#include <vector>

namespace lookahead::planner::detail {

/// For every cell of a width x height row-major raster, the squared distance in cells^2 from
/// its centre to the nearest centre with seed[i] != 0; kNoSeed when there is no seed at all.
std::vector<double> squared_distance_transform(const std::vector<std::uint8_t>& seed, int width, int height);

inline constexpr double kNoSeed = 1e20;

}  // namespace lookahead::planner::detail
