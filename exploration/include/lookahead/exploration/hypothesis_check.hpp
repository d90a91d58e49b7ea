// SPDX-License-Identifier: MIT
// How right a hypothesis was, measured against the true world (the paper measured its
// hypotheses against the final built map, sec. V-A.2; the simulator knows the truth).
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/world.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"

namespace lookahead::exploration {

struct HypothesisCheck {
  /// Psi (eq. 5) between the hypothesis and the world as a robot observes it, over the
  /// hypothesis' cells (the paper's measure against the final built map, sec. V-A.2).
  double psi = 0.0;
  /// The same against every world cell, the solid space beyond the outer walls and inside
  /// thick walls included, which no robot observes (reported beside psi for comparison).
  double psi_solid_world = 0.0;
  std::size_t cells = 0;    ///< predicted cells
  std::size_t correct = 0;  ///< ... whose class (wall or free) the world confirms
  /// Predicted wall cells, and those with a true wall within the tolerance: the cells a
  /// gain seen through the prediction decides with (predicted free cells still count as
  /// unexplored there).
  std::size_t wall_cells = 0, walls_correct = 0;
  /// The two sides of Psi: wall samples (similarity_resolution cells) in the hypothesis, and
  /// in the world over the same samples (what tells a wrong wall from a missed one).
  int predicted_walls = 0, world_walls = 0;
  [[nodiscard]] double accuracy() const { return cells ? static_cast<double>(correct) / cells : 0.0; }
};

/// One predicted cell at (x, y) against the world (the rule below).
bool prediction_matches_world(bool predicted_wall, const World& world, double x, double y, double wall_tolerance = 0.1);

/// A predicted wall is correct when a true wall lies within `wall_tolerance` of it (a wall
/// one cell off is the same wall), a predicted free cell when the world is free there.
/// `observable`: World::cells()-shaped mask of the cells a robot can observe
/// (observable_cells()); empty: every cell.
HypothesisCheck check_against_world(const slam::HypothesisMap& hypothesis, const World& world,
                                    const std::vector<std::uint8_t>& observable, double occupied_threshold,
                                    double wall_tolerance = 0.1, double similarity_resolution = 0.1,
                                    int similarity_tolerance_cells = 1);

/// The look-ahead map's cells that a target choice reads: those predicted and still
/// unexplored, within the observable part of the world (`observable`, as above; the
/// predictions beyond the outer walls no choice reaches), summed over choices.
struct PredictionInUse {
  std::size_t cells = 0, correct = 0;
  std::size_t wall_cells = 0, walls_correct = 0;  ///< the walls a gain seen through the prediction stops at
};

/// Adds the cells of `look_ahead` predicted on `map` now to `in_use`, each scored by
/// prediction_matches_world().
void score_prediction_in_use(const PredictedMap& look_ahead, const slam::OccupancyGrid& map, const World& world,
                             const std::vector<std::uint8_t>& observable, double occupied_threshold,
                             PredictionInUse& in_use);

}  // namespace lookahead::exploration
