// SPDX-License-Identifier: MIT
// Every parameter of the environmental-structure predictor (Chang et al. 2007, sec. III),
// in one place. Defaults follow the paper where it gives a value.
#pragma once

#include <cstdint>

#include "lookahead/predictor/map_features.hpp"

namespace lookahead::predictor {

struct PredictorOptions {
  FeatureOptions features;
  /// d: diameter of the surroundings S_f of the target and of the prediction range [m]
  /// (paper: 10 m).
  double surroundings_diameter = 10.0;
  /// The control point is the corner nearest to the target within this range [m] (the
  /// paper's "preset range", no value given); none in range: no prediction.
  double control_point_range = 3.0;
  /// Psi threshold for a hypothesis (paper: 0.6; allowed 0.4..0.7).
  double similarity_threshold = 0.6;
  /// Psi is measured on cells of this side [m] (the paper's map resolution, 0.1 m): our
  /// maps are finer (0.05 m) and a wall is one fine cell thick.
  double similarity_resolution = 0.1;
  /// Occupied cells this many similarity cells apart still overlap in Psi: corner positions
  /// from Hough lines are uncertain by about a cell, and exact overlap of one-cell walls
  /// would under-score a correct alignment (deviation, see similarity.hpp).
  int similarity_tolerance_cells = 1;
  /// Search bound (sec. III-A): at most this many reference corners are tried (x 4
  /// rotations each); beyond it a seeded random subset.
  int max_reference_corners = 150;
  /// Reference corners closer than this to the control point are the target's own [m].
  double min_reference_distance = 1.0;
  /// A hypothesis must predict at least this much unexplored area [m^2]; a reference
  /// that explains only explored cells predicts nothing.
  double min_predicted_area = 1.0;
  /// Beyond the paper: an alignment that puts more than this share of its walls on the
  /// other map's explored free cells is rejected whatever its Psi (eq. 5 looks at occupied
  /// cells only, so in a symmetric building a wall laid across a known corridor goes
  /// unnoticed and the hypothesis fills a pillar with free space).
  double max_conflict_share = 0.1;
  /// Beyond the paper, > 0: each prediction first registers surroundings this wide [m] with
  /// at most `large_max_conflict_share` of the walls on explored free cells, and only when
  /// that gives no hypothesis the surroundings of `surroundings_diameter` with
  /// `max_conflict_share`. Where the building repeats itself over large stretches (a
  /// symmetric maze) the wide window reaches further and is as right; where it does not, it
  /// rarely matches, and the fallback keeps the hypotheses of the smaller window. 0: off.
  double large_surroundings_diameter = 0.0;
  double large_max_conflict_share = 0.05;
  std::uint64_t seed = 1;  ///< of the random subset of reference corners
};

/// Throws std::invalid_argument naming the first option out of range.
void validate(const PredictorOptions& options);

}  // namespace lookahead::predictor
