// SPDX-License-Identifier: MIT
// A P-SLAM hypothesis (Chang, Lee, Lu, Hu, IEEE T-RO 2007, sec. IV-B): a predicted map of
// a region the robot has not explored yet, and the options of its use in the weights.
// The predictor (predictor/) makes hypotheses; the filter only reads them.
#pragma once

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::slam {

struct HypothesisMap {
  /// Predicted cells only: a cell is covered by the hypothesis when it is known here. Its
  /// frame is the map frame of the particle it was predicted on (the best one).
  OccupancyGrid grid;
  /// Similarity Psi (P-SLAM eq. (5)) of the registration the hypothesis came from, in [0, 1].
  double similarity = 0.0;
};

struct PredictionOptions {
  /// Use hypotheses in the weights (P-SLAM eq. (21)-(22)). Off: the filter is plain RBPF, bit for bit.
  bool enabled = false;
  /// hr_Th of the recovery rule (P-SLAM eq. (23)): when every particle's hit ratio on the predicted
  /// beams is below it, the prediction is not used for that scan. The paper gives no value;
  /// 0.5 = at least half the predicted end points must land on a predicted wall.
  double hit_ratio_threshold = 0.5;
  /// Fewer predicted end points than this carry no evidence; S2 is left out (1 = always).
  int min_predicted_beams = 8;
  /// Hypotheses kept at once (the oldest is dropped): each new target brings one.
  int max_hypotheses = 4;
};

}  // namespace lookahead::slam
