// SPDX-License-Identifier: MIT
// The picture of one prediction (like Fig. 5 of Chang et al. 2007): the explored map, the
// target region around the frontier cell and the reference region it was matched to, the
// two control points, every corner feature, and the hypothesis in colour (predicted walls
// blue, predicted free space pale blue).
#pragma once

#include <string>
#include <vector>

#include "lookahead/predictor/structure_predictor.hpp"
#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::predictor {

/// Predicted cells as picture overlays: occupied and free in two colours.
std::vector<slam::PicturePoints> hypothesis_overlays(const slam::HypothesisMap& h, double occupied_threshold);

void write_prediction_picture(const std::string& png_path, const slam::OccupancyGrid& map,
                              const Prediction& prediction, const PredictorOptions& options);

}  // namespace lookahead::predictor
