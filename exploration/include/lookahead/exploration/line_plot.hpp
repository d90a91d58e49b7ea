// SPDX-License-Identifier: MIT
// Line plots as PNG (coverage over time, study curves): axes with ticks, one colour per
// series, a legend. Drawn with OpenCV so no plotting stack is needed.
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::exploration {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  slam::Rgb colour;
};

struct PlotOptions {
  std::string title, x_label, y_label;
  int width = 800, height = 500;  ///< [px]
  double y_min = 0.0, y_max = 1.0;
};

void write_line_plot(const std::string& png_path, const std::vector<PlotSeries>& series, const PlotOptions& options);

/// Well-separated colours for series i = 0, 1, ...
slam::Rgb series_colour(std::size_t i);

}  // namespace lookahead::exploration
