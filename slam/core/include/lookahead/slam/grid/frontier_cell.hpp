// SPDX-License-Identifier: MIT
// The frontier cell (Yamauchi 1997, "A frontier-based approach for autonomous exploration"):
// a free cell with unexplored space among its 4-neighbours. One definition for every user:
// the exploration's frontier detector and the log replay's prediction targets, each with
// its own rule.
#pragma once

#include "lookahead/slam/grid/cell_index.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::slam {

struct FrontierCellRule {
  double free_threshold = 0.35;      ///< a known cell below this occupancy is free, (0, 0.5)
  double occupied_threshold = 0.65;  ///< at or above this it is an obstacle, (0.5, 1)
  /// Undecided cells whose evidence leans free (occupancy in [free, 0.5]) this many cells
  /// (Chebyshev) from never-seen space count as unexplored too; < 0: only never-seen cells do.
  int undecided_band = -1;
  /// A free cell that touches a cell whose evidence leans occupied (occupancy > 0.5,
  /// 8-neighbourhood) is not a frontier.
  bool skip_wall_cells = false;
};

class FrontierCellTest {
 public:
  /// Throws std::invalid_argument when a threshold is out of its range.
  explicit FrontierCellTest(const FrontierCellRule& rule = {});

  [[nodiscard]] bool is_free(const OccupancyGrid& grid, CellIndex c) const {
    const int l = grid.raw_log_odds(c);
    return l != GridTile::kUnknown && l < free_from_;
  }
  [[nodiscard]] bool is_occupied(const OccupancyGrid& grid, CellIndex c) const {
    const int l = grid.raw_log_odds(c);
    return l != GridTile::kUnknown && l >= occupied_from_;
  }
  [[nodiscard]] bool is_frontier(const OccupancyGrid& grid, CellIndex c) const;

 private:
  [[nodiscard]] bool is_unexplored(const OccupancyGrid& grid, CellIndex c) const;
  [[nodiscard]] bool leans_occupied(const OccupancyGrid& grid, CellIndex c) const {
    const int l = grid.raw_log_odds(c);
    return l != GridTile::kUnknown && l > 0;
  }

  FrontierCellRule rule_;
  // The thresholds as fixed-point log-odds: the first value whose probability reaches each.
  int free_from_ = 0, occupied_from_ = 0;
};

}  // namespace lookahead::slam
