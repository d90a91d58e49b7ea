// SPDX-License-Identifier: MIT
// Metric positions and waypoint paths of the planner. A position is not a cell index
// (slam::CellIndex) and not a pose (slam::Pose2): the planner works on the robot's centre only.
#pragma once

#include <vector>

namespace lookahead::planner {

/// A position in the map frame [m].
struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(Point2 a, Point2 b) { return !(a == b); }
};

/// Waypoints joined by straight segments, start first.
using Path = std::vector<Point2>;

/// Euclidean distance between two positions [m].
[[nodiscard]] double distance(Point2 a, Point2 b);

/// Sum of the segment lengths [m]; 0 for fewer than two waypoints.
[[nodiscard]] double path_length(const Path& path);

}  // namespace lookahead::planner
