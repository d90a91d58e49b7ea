// SPDX-License-Identifier: MIT
// Grouped bar charts as PNG (a study's mean time to 95 % per world and strategy): one group
// per world, one coloured bar per series with a +- whisker, a legend. Drawn with OpenCV, like
// line_plot.hpp, so no plotting stack is needed.
#pragma once

#include <string>
#include <vector>

namespace lookahead::exploration {

struct Bar {
  bool present = false;  ///< false: no value (drawn as "n/a")
  double value = 0.0;    ///< bar height, >= 0
  double whisker = 0.0;  ///< drawn from value - whisker to value + whisker, >= 0
  int count = -1;        ///< how many runs the bar averages, written above it ("n=3"); < 0: none
};

struct BarChart {
  std::string title, y_label;
  std::vector<std::string> groups;     ///< x axis: one label per group
  std::vector<std::string> series;     ///< legend: one colour each (series_colour)
  std::vector<std::vector<Bar>> bars;  ///< [group][series]
  int width = 900, height = 500;       ///< [px]
};

/// Throws slam::ParseError when the file cannot be written.
void write_bar_chart(const std::string& png_path, const BarChart& chart);

}  // namespace lookahead::exploration
