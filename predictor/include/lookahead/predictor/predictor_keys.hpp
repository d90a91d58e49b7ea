// SPDX-License-Identifier: MIT
// The YAML keys of the predictor's options, listed once: the mission's `lookahead:` section
// and the log replay's `predictor:` section both visit them, so the names cannot drift.
#pragma once

#include "lookahead/predictor/predictor_options.hpp"

namespace lookahead::predictor {

/// Visits every PredictorOptions field with (key, field, doc); the caller opens the section.
template <typename V>
void visit_predictor_keys(PredictorOptions& o, V&& v) {
  v("surroundings_diameter", o.surroundings_diameter, "d: surroundings S_f and prediction range [m]");
  v("control_point_range", o.control_point_range, "control point: nearest corner within [m]");
  v("similarity_threshold", o.similarity_threshold, "Psi for a hypothesis, 0.4..0.7");
  v("similarity_resolution", o.similarity_resolution, "Psi is measured on cells of [m]");
  v("similarity_tolerance_cells", o.similarity_tolerance_cells, "walls this many Psi cells apart overlap");
  v("max_reference_corners", o.max_reference_corners, "search bound: reference corners tried");
  v("min_reference_distance", o.min_reference_distance, "reference corners at least this far from P1 [m]");
  v("min_predicted_area", o.min_predicted_area, "a hypothesis predicts at least [m^2]");
  v("max_conflict_share", o.max_conflict_share, "alignments with more walls on known free cells are rejected");
  v("large_surroundings_diameter", o.large_surroundings_diameter, "> 0: try surroundings this wide first [m]");
  v("large_max_conflict_share", o.large_max_conflict_share, "... with at most this conflict share");
}

}  // namespace lookahead::predictor
