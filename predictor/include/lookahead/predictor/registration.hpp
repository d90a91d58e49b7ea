// SPDX-License-Identifier: MIT
// Search for a reference region (Chang et al. 2007, sec. III-A): a pair of control points,
// the target's corner P1 and a reference corner P2 elsewhere in the explored map, gives four
// rotations theta = phi_i(P1) - phi_j(P2) from the corners' line angles, and with each the
// transform Gamma of eq. 2 that lays the reference region over the target region. Each
// aligned reference region is scored with Psi (eq. 5); the best one wins.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "lookahead/predictor/map_features.hpp"
#include "lookahead/predictor/predictor_options.hpp"
#include "lookahead/predictor/similarity.hpp"
#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::predictor {

struct Alignment {
  /// Gamma: p_target = T (+) p_reference. Eq. 2 writes the translation as P1 - P2 with the
  /// rotation about the origin; we rotate about P2, so that P2 lands on P1 for every theta.
  slam::Pose2 reference_to_target;
  Corner control;    ///< P1, in the target region
  Corner reference;  ///< P2
  SimilarityScore score;
};

/// The four transforms of eq. 2 for the control points (P1, P2).
std::array<slam::Pose2, 4> corner_alignments(const Corner& control, const Corner& reference);

struct Registration {
  /// Highest Psi among alignments that predict something; when every alignment fell below
  /// the screen (Psi on a quarter of the samples), the best of those, scored on that quarter.
  std::optional<Alignment> best;
  int candidates = 0;  ///< transforms scored
};

/// Tries every reference corner (bounded by options.max_reference_corners) against the
/// control point over the target region's samples.
Registration register_region(const CoarseOccupancy& map, const RegionSamples& target_region, const Corner& control,
                             const std::vector<Corner>& corners, const PredictorOptions& options);

}  // namespace lookahead::predictor
