// SPDX-License-Identifier: MIT
// Small helpers the line and bar plots share (internal header).
#pragma once

#include <cmath>
#include <opencv2/core.hpp>

#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::exploration::plot {

inline cv::Scalar bgr(slam::Rgb c) { return {double(c.b), double(c.g), double(c.r)}; }

/// A round tick step (1, 2 or 5 times a power of ten) giving about five ticks over `span`.
inline double tick_step(double span) {
  const double raw = span / 5.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (raw <= m * p) return m * p;
  }
  return 10.0 * p;
}

}  // namespace lookahead::exploration::plot
