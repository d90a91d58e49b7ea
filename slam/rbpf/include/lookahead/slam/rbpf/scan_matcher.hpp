// SPDX-License-Identifier: MIT
// Hill-climbing scan matcher on the likelihood field: finds the mode of p(z | x, m) near the
// odometry prediction, the first step of the improved proposal (Grisetti et al. 2007,
// sec. III-A: "x_t^(i) is computed by a scan matcher").
#pragma once

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

struct ScanMatcherOptions {
  double linear_step = 0.05;  ///< first step in x and y [m]; halved at each refinement
  /// first step in theta [rad], halved at each refinement; a match given a larger angular
  /// reach starts at the reach, with as many more halvings (the finest step stays)
  double angular_step = 0.05;
  int refinements = 5;       ///< number of halvings
  int max_iterations = 100;  ///< cap on accepted moves (bounds the cost per particle)
  /// The match fails (and the proposal falls back to odometry) when fewer end points than
  /// this share lie near an obstacle of the map.
  double min_hit_ratio = 0.3;
  /// ... or when the mode lies farther than this from the odometry prediction [m].
  double max_correction = 0.6;
};

struct MatchResult {
  Pose2 pose;
  double log_likelihood = 0.0;
  double hit_ratio = 0.0;
  int evaluations = 0;
  bool ok = false;
};

class ScanMatcher {
 public:
  ScanMatcher(const ScanMatcherOptions& options, const LikelihoodFieldModel& model)
      : options_(options), model_(model) {}

  /// Climbs from `start`. `angular_reach` [rad]: the first angular step is at least this
  /// (the odometry's rotation std), so a misread turn is within the first steps' reach.
  /// `lookup`: how end points read the distance field (LikelihoodFieldModel::log_likelihood).
  [[nodiscard]] MatchResult match(const OccupancyGrid& grid, const Pose2& start, const PreparedScan& scan,
                                  double angular_reach = 0.0, FieldLookup lookup = FieldLookup::kCell) const;

 private:
  ScanMatcherOptions options_;
  const LikelihoodFieldModel& model_;
};

}  // namespace lookahead::slam
