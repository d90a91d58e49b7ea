// SPDX-License-Identifier: MIT
// Frontiers of an occupancy grid (Yamauchi 1997, "A frontier-based approach for autonomous
// exploration"): free cells next to unknown space, kept up to date incrementally (only the
// region a scan touched is re-examined) and grouped into clusters with a reachable goal each.
#pragma once

#include <cstdint>
#include <unordered_set>
#include <vector>

#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/frontier_cell.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

struct FrontierOptions {
  double free_threshold = 0.35;      ///< a known cell below this occupancy is free, (0, 0.5)
  double occupied_threshold = 0.65;  ///< at or above this it is an obstacle, (0.5, 1)
  int min_cluster_cells = 6;         ///< smaller clusters are noise (a gap between beams)
  /// Frontier cells this many cells apart still join one cluster, 1..5: far from the sensor
  /// the beams of a scan leave gaps in a frontier arc, which would split it into specks.
  int cluster_gap = 1;
  double robot_radius = 0.25;       ///< a goal needs this clearance from obstacles [m]
  double goal_search_radius = 1.0;  ///< how far from its cluster a goal may be moved [m]
};

struct FrontierCluster {
  std::vector<slam::CellIndex> cells;
  double centroid_x = 0.0, centroid_y = 0.0;  ///< [m]
  bool has_goal = false;                      ///< false when no free cell with clearance is near the cluster
  double goal_x = 0.0, goal_y = 0.0;          ///< [m]
};

struct CellHash {
  std::size_t operator()(slam::CellIndex c) const {
    return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) << 32) |
                                      static_cast<std::uint32_t>(c.y));
  }
};

class FrontierDetector {
 public:
  explicit FrontierDetector(const FrontierOptions& options = {});

  /// Re-examines the cells in [min, max] (inclusive) and their border; everything else
  /// keeps its previous state. Call with the bounding box of each inserted scan.
  void update(const slam::OccupancyGrid& grid, slam::CellIndex min, slam::CellIndex max);
  /// Re-examines the whole known part of the grid (after a change of best particle, whose
  /// map may differ anywhere).
  void rebuild(const slam::OccupancyGrid& grid);

  /// Frontier cells within `radius` [m] of (x, y) stop being frontiers for good: the robot
  /// stood there and they stayed, so the unknown space behind them cannot be seen (the
  /// inside of a wall seen from both sides, gaps between grazing beams). Returns how many.
  std::size_t retire_near(const slam::OccupancyGrid& grid, double x, double y, double radius);

  [[nodiscard]] const std::unordered_set<slam::CellIndex, CellHash>& cells() const { return cells_; }
  [[nodiscard]] std::size_t retired_count() const { return retired_.size(); }
  /// Clusters (cells within cluster_gap of each other) of at least min_cluster_cells, each
  /// with a goal if one exists.
  [[nodiscard]] std::vector<FrontierCluster> clusters(const slam::OccupancyGrid& grid) const;

  [[nodiscard]] bool is_free(const slam::OccupancyGrid& grid, slam::CellIndex c) const;
  [[nodiscard]] bool is_frontier(const slam::OccupancyGrid& grid, slam::CellIndex c) const;

 private:
  bool find_goal(const slam::OccupancyGrid& grid, FrontierCluster& cluster) const;
  bool has_clearance(const slam::OccupancyGrid& grid, slam::CellIndex c) const;

  /// Occupied cell (known, at or above the occupied threshold).
  bool is_occupied(const slam::OccupancyGrid& grid, slam::CellIndex c) const;

  FrontierOptions options_;
  slam::FrontierCellTest cell_test_;
  std::unordered_set<slam::CellIndex, CellHash> cells_;
  std::unordered_set<slam::CellIndex, CellHash> retired_;
};

}  // namespace lookahead::exploration
