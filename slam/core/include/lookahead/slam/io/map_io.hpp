// SPDX-License-Identifier: MIT
// Occupancy maps on disk in the ROS map_server convention: a PGM image plus a YAML file with
// resolution, origin and thresholds (http://wiki.ros.org/map_server, "Map format").
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::slam {

/// A map read back from disk: occupancy probability per pixel, -1 for unknown (pictures
/// also accept -0.5: unknown to the robot, an obstacle in the true world).
/// Row 0 is the bottom row (y grows up), unlike the image file.
struct ProbabilityMap {
  int width = 0;
  int height = 0;
  double resolution = 0.05;
  double origin_x = 0.0;
  double origin_y = 0.0;
  std::vector<double> p;  ///< width * height, row-major from the bottom

  [[nodiscard]] double at(int x, int y) const { return p[static_cast<std::size_t>(y * width + x)]; }
};

/// Rasterises a grid over its known bounds (plus a margin in cells).
ProbabilityMap to_probability_map(const OccupancyGrid& grid, int margin_cells = 10);

/// The inverse: a grid (with `options`, its resolution replaced by the map's) holding each
/// known pixel's probability as log-odds; unknown pixels stay unknown.
OccupancyGrid to_occupancy_grid(const ProbabilityMap& map, GridOptions options = {});

/// Writes DIR/NAME.pgm and DIR/NAME.yaml. Free 254, occupied 0, unknown 205 (map_server).
void write_map(const ProbabilityMap& map, const std::string& dir, const std::string& name);
/// Reads a map_server YAML (and the image it names) back; errors name the file and key.
ProbabilityMap read_map(const std::string& yaml_path);

}  // namespace lookahead::slam
