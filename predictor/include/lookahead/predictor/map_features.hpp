// SPDX-License-Identifier: MIT
// Structure features of an occupancy grid for P-SLAM (Chang, Lee, Lu, Hu, IEEE T-RO 2007,
// sec. III-A): line segments found by the Hough transform on occupied cells, and corners,
// each carrying the directions of its two lines, from line intersections and from image
// gradients. Registration (eq. 2) turns a corner's two line angles into candidate rotations.
#pragma once

#include <vector>

#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::predictor {

struct LineSegment {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< end points [m]
  [[nodiscard]] double length() const;
  [[nodiscard]] double angle() const;  ///< direction of (x1 - x0, y1 - y0) [rad]
};

struct Corner {
  enum class Source { kLineIntersection, kGradient };
  double x = 0, y = 0;  ///< [m]
  /// Directions of the two lines, each pointing from the corner along its segment [rad].
  double angle_a = 0, angle_b = 0;
  Source source = Source::kLineIntersection;
};

struct FeatureOptions {
  double occupied_threshold = 0.65;    ///< cells at or above this occupancy are walls, (0.5, 1)
  int hough_votes = 12;                ///< accumulator votes for a line (cells on it), >= 2
  double min_line_length = 0.6;        ///< shorter segments are clutter [m]
  double max_line_gap = 0.2;           ///< gaps a segment may bridge (missed wall cells) [m]
  double corner_reach = 0.3;           ///< a corner's lines must end this close to it [m]
  double min_corner_angle = 0.5;       ///< lines meeting at less than this are not a corner [rad]
  int max_gradient_corners = 400;      ///< cap on Shi-Tomasi candidates (bounds the cost)
  double gradient_quality = 0.05;      ///< Shi-Tomasi quality level relative to the best, (0, 1)
  double min_corner_separation = 0.3;  ///< corners closer than this are one corner [m]
};

struct MapFeatures {
  std::vector<LineSegment> lines;
  std::vector<Corner> corners;
};

/// Features of the cells in [lo, hi] (inclusive); the whole known grid when lo > hi.
MapFeatures extract_features(const slam::OccupancyGrid& grid, const FeatureOptions& options,
                             slam::CellIndex lo = {1, 1}, slam::CellIndex hi = {0, 0});

}  // namespace lookahead::predictor
