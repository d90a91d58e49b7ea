// SPDX-License-Identifier: MIT
// The P-SLAM figures of a finished mission: how many predictions were made and why the
// others were not, how similar each hypothesis was to the true world (the paper's Fig. 10
// measure), how much of the look-ahead map was right, and how often the filter used it.
#pragma once

#include <cstddef>
#include <vector>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/exploration/world_reachability.hpp"

namespace lookahead::exploration {

struct PredictionSummary {
  bool enabled = false;
  int requests = 0, hypotheses = 0, no_control_point = 0, no_match = 0;
  std::vector<double> psi_world;                     ///< per hypothesis: Psi against the observable true world
  std::vector<double> psi_solid_world;               ///< ... against every world cell (HypothesisCheck)
  std::vector<PredictionRecord> hypothesis_records;  ///< the requests that made a hypothesis
  double mean_psi_world = 0.0;
  double share_psi_world_above_04 = 0.0;
  double predicted_area = 0.0;                   ///< summed over hypotheses [m^2]
  double cell_accuracy = 0.0;                    ///< predicted cells whose class the world confirms
  double mean_seconds = 0.0, max_seconds = 0.0;  ///< wall time per prediction
  /// The predicted cells the strategy's target choices read (LookaheadMapping::score_choice).
  PredictionInUse in_use;
  /// The look-ahead map at the end: cells predicted and still unexplored.
  double final_predicted_area = 0.0;  ///< [m^2]
  double final_predicted_accuracy = 0.0;
  /// The same over the cells the robot could observe: within kObservableMargin of the
  /// reachable area. Outside it lie predictions beyond the outer walls and deep inside
  /// pillars, which no robot can check (the paper's Fig. 7(d) discards them by "assuming
  /// the environmental boundary is known").
  double final_predicted_area_inside = 0.0;  ///< [m^2]
  double final_predicted_accuracy_inside = 0.0;
  /// Coverage counting predicted free cells the world confirms as covered.
  double coverage_with_predictions = 0.0;
  /// P-SLAM's skip protocol (sec. V-A.1), read off the mission's curve, reported apart
  /// from the explored metric: when every frontier left was first predicted
  /// (MissionStatistics::rest_predicted_time), when explored or correctly predicted reached
  /// the coverage goal, and the first of the two, with that coverage then [s, simulated;
  /// < 0: never].
  double rest_predicted_time = -1.0;
  double time_to_goal_with_predictions = -1.0;
  double skip_protocol_end = -1.0;
  double coverage_with_predictions_at_skip_end = 0.0;
  double path_at_skip_end = 0.0;  ///< [m]
  std::size_t filter_hypotheses = 0, filter_predicted_updates = 0, filter_used = 0, filter_rejected = 0;
};

PredictionSummary summarize_predictions(const Mission& mission);

}  // namespace lookahead::exploration
