// SPDX-License-Identifier: MIT
// How well a mission explored: coverage of the reachable free area over time, the time and
// path length to 90/95/99 % coverage, and the map's precision and recall against the world.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "lookahead/exploration/world.hpp"
#include "lookahead/exploration/world_reachability.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

/// Samples reachable free cells of the world (on a ~10 cm lattice) and counts those the
/// map has observed (any evidence, free or occupied).
class CoverageMeter {
 public:
  CoverageMeter(const World& world, const ReachableArea& area);
  [[nodiscard]] double coverage(const slam::OccupancyGrid& map) const;  ///< in [0, 1]
  /// Coverage counting also the samples `also_covered(x, y)` accepts (predicted free cells).
  [[nodiscard]] double coverage(const slam::OccupancyGrid& map,
                                const std::function<bool(double, double)>& also_covered) const;
  [[nodiscard]] std::size_t samples() const { return points_.size(); }

 private:
  std::vector<std::pair<double, double>> points_;
};

struct CoverageSample {
  double time = 0.0;         ///< simulated [s]
  double path_length = 0.0;  ///< travelled [m]
  double coverage = 0.0;     ///< [0, 1]
  /// With look-ahead mapping: explored, or predicted free where the world is free.
  double coverage_with_predictions = 0.0;
};

struct Milestone {
  double level = 0.0;
  bool reached = false;
  double time = 0.0, path_length = 0.0;
};

/// First time (and distance) at which coverage reached 0.90, 0.95 and 0.99.
std::array<Milestone, 3> coverage_milestones(const std::vector<CoverageSample>& curve);

struct MapQuality {
  double precision = 0.0;  ///< map obstacles that are world obstacles (within one cell)
  double recall = 0.0;     ///< world walls facing reachable space that the map has found
  std::size_t map_obstacles = 0, world_walls = 0;
};

MapQuality map_quality(const slam::OccupancyGrid& map, const World& world, const ReachableArea& area,
                       double occupied_threshold = 0.65);

}  // namespace lookahead::exploration
