// SPDX-License-Identifier: MIT
#include "lookahead/slam/sensor/laser_scan.hpp"

#include <cmath>

namespace lookahead::slam {

bool LaserScan::is_return(std::size_t beam) const {
  const float r = ranges[beam];
  return std::isfinite(r) && r > 0.0f && r < max_range;
}

}  // namespace lookahead::slam
