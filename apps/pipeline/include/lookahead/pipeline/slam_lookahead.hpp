// SPDX-License-Identifier: MIT
// P-SLAM on a laser log (`lookahead slam --predict`): a log has no exploration goals, so the
// target is one a robot driving this way could pick next -- a frontier cell within the
// sensor range and ahead of it (within `half_angle` of its heading). The worker takes the
// nearest such cell that has a control point in range: the nearest frontier cell alone
// is mostly a gap between beams along a wall with no corner near it (fr101: 38 of 57
// requests had no control point).
// Predictions run on the worker thread and reach the filter `latency_updates` after the
// request. A replay runs far faster than the log's clock (Intel: 550x real time), so by
// default it waits for a prediction that is late (`wait_for_predictions`), as a robot's
// filter, updating at the sensor's rate, would have it in time; runs are then repeatable.
// Without waiting the filter never stalls and takes a late prediction at a later update,
// which starves the predictor on a fast replay (Intel, 40 particles: 4 requests in a run
// instead of 98) and makes a run depend on the machine's speed. Off, plain RBPF bit for bit.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "lookahead/predictor/prediction_worker.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"

namespace lookahead::pipeline {

struct SlamLookaheadOptions {
  int period_updates = 10;           ///< a new target every this many filter updates
  int latency_updates = 2;           ///< a prediction reaches the filter this many updates later
  double range = 8.0;                ///< frontier cells up to this far from the robot [m]
  double half_angle = 1.0;           ///< ... and within this of its heading [rad]
  bool wait_for_predictions = true;  ///< wait for a late prediction instead of taking it later
  int max_candidates = 12;           ///< frontier cells offered per request, nearest first
  double candidate_spacing = 0.5;    ///< candidates at least this far apart [m]
};

/// The frontier cell (free, with an unknown 4-neighbour) nearest to `pose` within the range
/// and the heading cone; nullopt when there is none.
std::optional<std::pair<double, double>> frontier_ahead(const slam::OccupancyGrid& map, const slam::Pose2& pose,
                                                        double range, double half_angle, double free_threshold = 0.35);
/// Up to `max_count` such frontier cells, nearest first, each at least `spacing` [m] from
/// the ones before it.
std::vector<std::pair<double, double>> frontiers_ahead(const slam::OccupancyGrid& map, const slam::Pose2& pose,
                                                       double range, double half_angle, int max_count, double spacing,
                                                       double free_threshold = 0.35);

/// One delivered prediction: where, what became of it, and its best alignment.
struct LogPredictionRecord {
  int update = 0;       ///< filter update at which it reached the filter
  double x = 0, y = 0;  ///< target [m], best particle's map frame
  predictor::Prediction::Status status = predictor::Prediction::Status::kNoControlPoint;
  double psi = 0, conflict_share = 0;  ///< of the best alignment (0 without one)
  double predicted_area = 0;           ///< [m^2]
};

struct SlamLookaheadStatistics {
  int requests = 0, hypotheses = 0, no_control_point = 0, no_match = 0;
  double seconds = 0.0;  ///< wall time of all predictions (on the worker thread)
  std::vector<LogPredictionRecord> records;
};

class SlamLookahead {
 public:
  SlamLookahead(const predictor::PredictorOptions& predictor, const SlamLookaheadOptions& options);
  /// Call after each filter update: delivers a due hypothesis, requests a new one on time.
  void after_update(slam::Rbpf& filter);
  [[nodiscard]] const SlamLookaheadStatistics& statistics() const { return stats_; }

 private:
  SlamLookaheadOptions options_;
  predictor::PredictionWorker worker_;
  SlamLookaheadStatistics stats_;
  int updates_ = 0, due_ = -1;
};

}  // namespace lookahead::pipeline
