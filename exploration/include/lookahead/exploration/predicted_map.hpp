// SPDX-License-Identifier: MIT
// The look-ahead map of a mission (Chang et al. 2007, sec. II-B): every hypothesis the
// predictor made, merged in the mission map's frame, each cell with the Psi of the
// hypothesis that predicted it. Validation (model V of eq. 20): a cell is predicted only
// while the robot's map has not explored it.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

/// Which frontiers look-ahead mapping covers, so that a predictive strategy skips them
/// (P-SLAM sec. II-B: "the robot can decide not to explore the predicted regions").
enum class SkipVariant {
  kFarSide,  ///< the share of unknown cells beside the frontier that is predicted (covered_share)
  kRegion,   ///< its unexplored region within region_radius is predicted (region_area)
};

/// lookahead.skip in YAML (a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<SkipVariant, const char*>, 2> choice_names(SkipVariant) {
  return {{{SkipVariant::kFarSide, "far_side"}, {SkipVariant::kRegion, "region"}}};
}

/// When look-ahead mapping covers a frontier (LookaheadOptions has the meaning of each).
struct SkipRule {
  double min_confidence = 0.6;  ///< hypotheses below this Psi do not count
  SkipVariant variant = SkipVariant::kFarSide;
  double region_radius = 7.0;     ///< kRegion: the region's reach from the goal [m], > 0
  double region_tolerance = 1.0;  ///< ... covered up to this much unpredicted area [m^2]
  double occupied = 0.65;         ///< predicted walls: probability at least this
  /// kRegion: unknown gaps up to this wide in a wall (explored or predicted)
  /// close the region as the wall would [m]; 0: only unbroken walls close it.
  double wall_gap = 0.0;
  /// kRegion: the environment's boundary, when known (P-SLAM Fig. 7(d)): no
  /// region reaches beyond it, where nothing can be explored or predicted [m].
  struct Extent {
    double min_x, min_y, max_x, max_y;
  };
  std::optional<Extent> boundary;
  /// kRegion: also leave out wall slivers, frontiers whose unexplored region is a
  /// closed pocket (RegionArea::wall_sliver): a wall seen at a grazing angle, a corner seen
  /// from afar, a gap into a pillar. Their region then also holds the cells seen but
  /// undecided (probability in [free, occupied)), as the frontier detector counts them
  /// unexplored: such a band alone made a frontier whose region was empty, and the robot
  /// drove to it (README, P-SLAM 1).
  bool skip_wall_slivers = false;
  double free = 0.35;  ///< with skip_wall_slivers: a seen cell below this is explored
};

/// A frontier's unexplored region (PredictedMap::region_area) [m^2].
struct RegionArea {
  double predicted = 0.0;             ///< by a hypothesis with the minimum Psi
  double unpredicted = 0.0;           ///< what driving there would still reveal
  bool closed_by_prediction = false;  ///< a predicted wall bounds it
  /// An unexplored cell within the radius was left out of it: in a wall gap or beyond the boundary.
  bool closed_by_gap = false;
  /// ... in a gap that only a predicted wall closes (counted with SkipRule::skip_wall_slivers).
  bool gap_of_prediction = false;
  /// Something of it is predicted: a predicted part or a predicted wall closing it. An
  /// empty region (the far side already seen) is not left out by any prediction.
  [[nodiscard]] bool touched_by_prediction() const { return predicted > 0 || closed_by_prediction; }
  /// Left out by look-ahead mapping: touched by a prediction, and at most `tolerance` of it
  /// is not predicted [m^2].
  [[nodiscard]] bool covered(double tolerance) const { return touched_by_prediction() && unpredicted <= tolerance; }
  /// A wall sliver: a closed pocket no prediction touches (nor closes by a gap), of at most
  /// `tolerance` [m^2], with something unexplored in it or left out of it as a wall gap or
  /// beyond the boundary.
  /// Not the empty region of a stale frontier, whose far side was seen since (nothing
  /// unexplored at all).
  [[nodiscard]] bool wall_sliver(double tolerance) const {
    return !touched_by_prediction() && !gap_of_prediction && unpredicted <= tolerance &&
           (unpredicted > 0 || closed_by_gap);
  }
};

/// Does the rule leave out the frontier whose region this is?
[[nodiscard]] inline bool left_out(const RegionArea& region, const SkipRule& rule) {
  return region.covered(rule.region_tolerance) || (rule.skip_wall_slivers && region.wall_sliver(rule.region_tolerance));
}

class PredictedMap {
 public:
  explicit PredictedMap(const slam::GridOptions& options = {}) : cells_(options) {}

  /// Merges a hypothesis; where hypotheses overlap, the more similar one (higher Psi) wins.
  void add(const slam::HypothesisMap& hypothesis);
  /// Covered by a hypothesis and not yet explored in `map`.
  [[nodiscard]] bool predicted(const slam::OccupancyGrid& map, slam::CellIndex c) const {
    return cells_.is_known(c) && !map.is_known(c);
  }
  /// Psi of the hypothesis that predicted the cell; 0 when none did.
  [[nodiscard]] double confidence(slam::CellIndex c) const;
  /// Share of the unknown 4-neighbours of the cluster's cells that are predicted with at
  /// least `min_confidence`: 1 when a look-ahead map already covers what lies beyond.
  [[nodiscard]] double predicted_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                       double min_confidence) const;
  /// The unexplored region beyond the frontier that no hypothesis with `min_confidence`
  /// predicts [m^2]: unknown cells within `radius` of the cluster's goal reachable from its
  /// far side through unknown cells, not through predicted walls (probability >=
  /// `occupied`), counting those not predicted. What driving there would still reveal.
  [[nodiscard]] double unpredicted_area(const slam::OccupancyGrid& map, const FrontierCluster& cluster, double radius,
                                        double min_confidence, double occupied) const {
    SkipRule rule;
    rule.min_confidence = min_confidence;
    rule.variant = SkipVariant::kRegion;
    rule.region_radius = radius;
    rule.region_tolerance = 0.0;
    rule.occupied = occupied;
    return region_area(map, cluster, rule).unpredicted;
  }
  /// The same region (within rule.region_radius, walls closing it with rule.wall_gap),
  /// split into its predicted and unpredicted parts.
  [[nodiscard]] RegionArea region_area(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                       const SkipRule& rule) const;
  /// The share of the cluster's far side that look-ahead mapping covers: under kRegion, 1
  /// when the region is left out (left_out()) and 0 otherwise; under kFarSide,
  /// predicted_share().
  [[nodiscard]] double covered_share(const slam::OccupancyGrid& map, const FrontierCluster& cluster,
                                     const SkipRule& rule) const;
  [[nodiscard]] const slam::OccupancyGrid& cells() const { return cells_; }
  [[nodiscard]] std::size_t hypotheses() const { return hypotheses_; }

 private:
  static std::int64_t key(slam::CellIndex c) {
    return (static_cast<std::int64_t>(c.x) << 32) ^ static_cast<std::uint32_t>(c.y);
  }
  slam::OccupancyGrid cells_;
  std::unordered_map<std::int64_t, float> confidence_;
  std::size_t hypotheses_ = 0;
};

}  // namespace lookahead::exploration
