// SPDX-License-Identifier: MIT
// The environmental-structure predictor of P-SLAM (Chang et al. 2007, sec. III), one call:
// features of the explored map, the control point nearest the target, registration of the
// target region against every reference corner, and -- when the best Psi clears the
// threshold -- the hypothesis: the aligned reference region over the cells of the target
// region that are still unexplored (sec. III-C).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "lookahead/predictor/map_features.hpp"
#include "lookahead/predictor/predictor_options.hpp"
#include "lookahead/predictor/registration.hpp"
#include "lookahead/predictor/similarity.hpp"
#include "lookahead/predictor/unexplored_region.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"

namespace lookahead::predictor {

struct Prediction {
  enum class Status { kPredicted, kNoControlPoint, kNoMatch };
  Status status = Status::kNoControlPoint;
  double target_x = 0, target_y = 0;                      ///< the frontier cell f [m]
  std::optional<Alignment> alignment;                     ///< best one found, also when below threshold
  int candidates = 0;                                     ///< transforms scored
  double predicted_area = 0.0;                            ///< cells in the hypothesis [m^2]
  double diameter = 0.0;                                  ///< of the surroundings registered last [m]
  double seconds = 0.0;                                   ///< wall time of the whole prediction
  MapFeatures features;                                   ///< of the explored map (for pictures)
  std::shared_ptr<const slam::HypothesisMap> hypothesis;  ///< set when kPredicted
};
const char* to_string(Prediction::Status status);

/// What every prediction on one explored map shares, computed once per map: the features
/// (the Hough transform and corners over the whole map, most of a prediction's cost) and
/// the coarse occupancy Psi is measured on.
struct ExploredMapModel {
  MapFeatures features;
  CoarseOccupancy coarse;
};
ExploredMapModel model_explored_map(const slam::OccupancyGrid& map, const PredictorOptions& options);

/// One prediction of the region around the target (tx, ty) on `map`.
Prediction predict_structure(const slam::OccupancyGrid& map, double tx, double ty, const PredictorOptions& options);
/// The same with the map's model already computed (several targets on one map).
Prediction predict_structure(const slam::OccupancyGrid& map, const ExploredMapModel& model, double tx, double ty,
                             const PredictorOptions& options);

/// The hypothesis of sec. III-C: every cell of the unexplored region (unexplored_region()) whose
/// aligned reference cell is explored takes that cell's occupancy.
std::shared_ptr<slam::HypothesisMap> make_hypothesis(const slam::OccupancyGrid& map, double tx, double ty,
                                                     double diameter, const slam::Pose2& reference_to_target);

}  // namespace lookahead::predictor
