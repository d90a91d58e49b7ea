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
  bool marks_start = true;  ///< the first path's first pose gets the start marker
};

struct PicturePoints {
  std::vector<std::pair<double, double>> points;  ///< [m]
  Rgb colour;
  std::string label;
  int radius = 2;  ///< [px]
  /// Draw each point as the filled map cell it lies in, not a dot (predicted cells).
  bool fill_cells = false;
};

/// An 8-bit BGR image in memory (row-major, top row first).
struct BgrImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;
};

/// The legend's white panel left of the map [pixels]: a map's x pixel in the picture is
/// kLegendPanelWidth + (x - origin_x) / resolution * scale.
constexpr int kLegendPanelWidth = 380;

/// Renders `map` with the paths and point sets drawn over it and a legend; the start of
/// the first path gets a marker unless it says otherwise. `title` goes in the legend's first line. Small maps are
/// scaled up so cells stay visible.
BgrImage render_map_picture(const ProbabilityMap& map, const std::vector<PicturePath>& paths,
                            const std::vector<PicturePoints>& points, const std::string& title);

/// render_map_picture() written to a PNG file.
void write_map_picture(const std::string& png_path, const ProbabilityMap& map, const std::vector<PicturePath>& paths,
                       const std::string& title, const std::vector<PicturePoints>& points = {});

}  // namespace lookahead::slam
