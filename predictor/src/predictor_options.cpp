// SPDX-License-Identifier: MIT
#include "lookahead/predictor/predictor_options.hpp"

#include <stdexcept>
#include <string>

namespace lookahead::predictor {

void validate(const PredictorOptions& o) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("predictor: " + what); };
  if (!(o.surroundings_diameter > 0)) fail("surroundings_diameter > 0");
  if (!(o.control_point_range > 0)) fail("control_point_range > 0");
  if (!(o.similarity_threshold >= 0.4 && o.similarity_threshold <= 0.7))
    fail("similarity_threshold in [0.4, 0.7] (sec. III-C)");
  if (!(o.similarity_resolution > 0)) fail("similarity_resolution > 0");
  if (o.similarity_tolerance_cells < 0 || o.similarity_tolerance_cells > 5) fail("similarity_tolerance_cells in 0..5");
  if (o.max_reference_corners < 1) fail("max_reference_corners >= 1");
  if (o.min_reference_distance < 0) fail("min_reference_distance >= 0");
  if (o.min_predicted_area < 0) fail("min_predicted_area >= 0");
  if (!(o.max_conflict_share >= 0 && o.max_conflict_share <= 1)) fail("max_conflict_share in [0, 1]");
  if (!(o.large_surroundings_diameter >= 0)) fail("large_surroundings_diameter >= 0");
  if (!(o.large_max_conflict_share >= 0 && o.large_max_conflict_share <= 1)) fail("large_max_conflict_share in [0, 1]");
}

}  // namespace lookahead::predictor
