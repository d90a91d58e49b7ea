// SPDX-License-Identifier: MIT
// How right a hypothesis was, measured against the true world (the paper measured its
// hypotheses against the final built map, sec. V-A.2; the simulator knows the truth).
#pragma once

#include "lookahead/exploration/world.hpp"
#include "lookahead/slam/rbpf/hypothesis.hpp"

namespace lookahead::exploration {

struct HypothesisCheck {
  double psi = 0.0;           ///< Psi (eq. 5) between the hypothesis and the world over its cells
  std::size_t cells = 0;      ///< predicted cells
  std::size_t correct = 0;    ///< ... whose class (wall or free) the world confirms
  [[nodiscard]] double accuracy() const { return cells ? static_cast<double>(correct) / cells : 0.0; }
};

/// One predicted cell at (x, y) against the world (the rule below).
bool prediction_matches_world(bool predicted_wall, const World& world, double x, double y,
                              double wall_tolerance = 0.1);

/// A predicted wall is correct when a true wall lies within `wall_tolerance` of it (a wall
/// one cell off is the same wall), a predicted free cell when the world is free there.
HypothesisCheck check_against_world(const slam::HypothesisMap& hypothesis, const World& world,
                                    double occupied_threshold, double wall_tolerance = 0.1,
                                    double similarity_resolution = 0.1, int similarity_tolerance_cells = 1);

}  // namespace lookahead::exploration
