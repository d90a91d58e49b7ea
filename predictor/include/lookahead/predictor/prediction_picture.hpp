// SPDX-License-Identifier: MIT
// The picture of one prediction (like Fig. 5 of Chang et al. 2007): the explored map, the
// target region around the frontier cell and the reference region it was matched to, the
// two control points, every corner feature, and the hypothesis in colour (predicted walls
// blue, predicted free space pale blue).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "lookahead/predictor/structure_predictor.hpp"
#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::predictor {

/// Known cells of `predicted` as picture overlays, free then walls in two colours; `show`
/// (optional) keeps only some cells (a mission shows those not explored yet).
std::vector<slam::PicturePoints> predicted_cell_overlays(const slam::OccupancyGrid& predicted,
                                                         double occupied_threshold,
                                                         const std::function<bool(slam::CellIndex)>& show = nullptr);

/// `extra` overlays are drawn over the map and under the hypothesis (e.g. true walls).
void write_prediction_picture(const std::string& png_path, const slam::OccupancyGrid& map, const Prediction& prediction,
                              const PredictorOptions& options, const std::vector<slam::PicturePoints>& extra = {});

}  // namespace lookahead::predictor
