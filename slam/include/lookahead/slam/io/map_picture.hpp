// SPDX-License-Identifier: MIT
// A picture of a map a person can read: occupancy in greys, unknown tinted, paths and
// markers in colour, and a legend.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/map_io.hpp"

namespace lookahead::slam {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct PicturePath {
  std::vector<Pose2> poses;
  Rgb colour;
  std::string label;
  int thickness = 2;
};

/// Writes a PNG of `map` with the paths drawn over it; the start of the first path gets a
/// marker. `title` goes in the legend's first line.
void write_map_picture(const std::string& png_path, const ProbabilityMap& map,
                       const std::vector<PicturePath>& paths, const std::string& title);

}  // namespace lookahead::slam
