// SPDX-License-Identifier: MIT
// Look-ahead mapping in a mission (Chang et al. 2007, Fig. 2 and 6): when the robot picks a
// new target, the predictor works on the target's surroundings on its own thread; the
// hypothesis joins the look-ahead map (and, with prediction on, the filter's weights).
// Every prediction is recorded and checked against the true world.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lookahead/exploration/hypothesis_check.hpp"
#include "lookahead/exploration/predicted_map.hpp"
#include "lookahead/exploration/world.hpp"
#include "lookahead/predictor/prediction_worker.hpp"

namespace lookahead::exploration {

struct LookaheadOptions {
  /// Make predictions at each new target (implied by --predict and the predictive strategy).
  bool enabled = false;
  predictor::PredictorOptions predictor;
  /// A prediction is delivered this long (simulated) after its request. The predictor runs
  /// on its own thread; a fixed simulated latency keeps runs reproducible whatever the
  /// machine's speed (the mission waits for the thread if it is slower) [s].
  double latency = 1.0;
  /// Which frontiers a predictive strategy skips, counting hypotheses with Psi >=
  /// `skip_confidence`. kFarSide: at least `skip_share` of the unknown cells beside the
  /// frontier are predicted (1.0: only what is fully predicted; 0.8 sent the robot
  /// zig-zagging between far frontiers on the maze). kRegion (the mission default): its
  /// unexplored region within `skip_region_radius` (the unknown cells reachable from its far
  /// side, closed by explored and predicted walls) has at most `min_predicted_area` that no
  /// hypothesis predicts.
  SkipVariant skip = SkipVariant::kFarSide;
  double skip_confidence = 0.6;
  double skip_share = 1.0;
  double skip_region_radius = 7.0;  ///< [m], > 0
  /// kRegion: unknown gaps up to this wide in a wall close the region [m].
  double skip_region_wall_gap = 0.0;
  /// kRegion: the environment's outer boundary is known, as in P-SLAM's
  /// Fig. 7(d) ("assuming that the environmental boundary is known"): the region of a
  /// frontier by the outer wall does not leak beyond it, where nothing can be predicted.
  /// The mission takes the boundary from the world's extent (on in MissionOptions::defaults();
  /// turn it off for a world whose extent is not the building's outline).
  bool known_boundary = false;
  /// kRegion: also skip wall slivers, frontiers whose unexplored region is a
  /// closed pocket of at most min_predicted_area that no prediction touches
  /// (SkipRule::skip_wall_slivers, RegionArea::wall_sliver).
  bool skip_wall_slivers = false;
  /// The rule of the options above.
  [[nodiscard]] SkipRule skip_rule() const {
    // The mission's free threshold and boundary are set by Mission::skip_rule().
    return SkipRule{}
        .with_variant(skip)
        .with_min_confidence(skip_confidence)
        .with_region_radius(skip_region_radius)
        .with_region_tolerance(predictor.min_predicted_area)
        .with_occupied(predictor.features.occupied_threshold)
        .with_wall_gap(skip_region_wall_gap)
        .with_wall_slivers(skip_wall_slivers);
  }
  /// Frontiers predicted per target selection: the chosen target first, then the nearest
  /// other frontier goals (the paper's extension "predict several possible targets",
  /// sec. II-A). They queue on the worker, one delivered per latency period.
  int targets_per_selection = 4;
  /// While the predictor has nothing queued (off here, on in MissionOptions::defaults()), predict the nearest frontier
  /// goals that the look-ahead map does not cover yet (targets_per_selection at a time), a goal again only
  /// `repredict_after` seconds after its last try and once the known cells of its surroundings (diameter
  /// predictor.surroundings_diameter) grew by `repredict_growth` (prediction_attempts.hpp). The paper predicts "the
  /// next possible exploration goal" (sec. II-A); every frontier is one, and a selection that knows which are predicted
  /// can leave them out.
  bool predict_while_idle = false;
  double repredict_after = 10.0;  ///< [s, simulated]
  double repredict_growth = 0.1;  ///< share of known cells, >= 0
  /// Keep the map and the prediction of every hypothesis and write one picture each into
  /// the run folder (predictions/NNN.png, with the true walls of the target region): for
  /// finding out why a hypothesis scored low against the world. Costs memory; off by default.
  bool pictures = false;
};

struct PredictionRecord {
  double time = 0.0;                              ///< simulated time of the request [s]
  double x = 0.0, y = 0.0;                        ///< target [m]
  std::string status;                             ///< predictor::to_string(Prediction::Status)
  double psi = 0.0;                               ///< best Psi of the registration (0 without a control point)
  double area = 0.0;                              ///< predicted area [m^2]
  double diameter = 0.0;                          ///< of the surroundings registered last (large or d) [m]
  double seconds = 0.0;                           ///< wall time of the prediction
  HypothesisCheck truth;                          ///< of the hypothesis against the world (when predicted)
  std::optional<predictor::Alignment> alignment;  ///< the best registration, when one was scored
};

/// One hypothesis with the map it was made on (kept with LookaheadOptions::pictures).
struct HypothesisSnapshot {
  std::size_t record = 0;  ///< index into LookaheadMapping::records()
  slam::OccupancyGrid map;
  predictor::Prediction prediction;
};

class LookaheadMapping {
 public:
  /// `observable`: the world cells a robot can observe (observable_cells()), over which each
  /// hypothesis is scored; empty: every cell.
  LookaheadMapping(const LookaheadOptions& options, const World& world, const slam::GridOptions& grid,
                   std::vector<std::uint8_t> observable = {});

  /// A new selection: predict around each target in turn, on a copy of `map` (copy-on-write:
  /// cheap). Targets still queued from the previous selection are dropped.
  void request(const slam::OccupancyGrid& map, const std::vector<std::pair<double, double>>& targets, double now);
  /// The hypothesis of the pending request once its latency has passed (null otherwise, or
  /// when no hypothesis cleared the threshold).
  std::shared_ptr<const slam::HypothesisMap> deliver(double now);
  /// Scores the look-ahead map as a target choice on `map` reads it (PredictionInUse,
  /// summed over the mission's choices).
  void score_choice(const slam::OccupancyGrid& map) {
    score_prediction_in_use(predicted_, map, world_, observable_, options_.predictor.features.occupied_threshold,
                            in_use_);
  }
  [[nodiscard]] const PredictionInUse& in_use() const { return in_use_; }
  /// Nothing running on the worker and nothing queued.
  [[nodiscard]] bool idle() const { return !pending_ && queued_.empty(); }

  [[nodiscard]] const PredictedMap& predicted() const { return predicted_; }
  [[nodiscard]] const std::vector<PredictionRecord>& records() const { return records_; }
  [[nodiscard]] const LookaheadOptions& options() const { return options_; }
  [[nodiscard]] const std::vector<HypothesisSnapshot>& snapshots() const { return snapshots_; }

 private:
  std::vector<HypothesisSnapshot> snapshots_;
  slam::OccupancyGrid pending_map_;  ///< the map of the pending request
  LookaheadOptions options_;
  const World& world_;
  std::vector<std::uint8_t> observable_;
  predictor::PredictionWorker worker_;
  PredictedMap predicted_;
  std::vector<PredictionRecord> records_;
  PredictionInUse in_use_;
  void start_next(double now);

  slam::OccupancyGrid queued_map_;
  std::vector<std::pair<double, double>> queued_;  ///< targets not started yet
  bool pending_ = false;                           ///< one is running on the worker
  double due_ = 0.0;
  PredictionRecord pending_record_;
};

}  // namespace lookahead::exploration
