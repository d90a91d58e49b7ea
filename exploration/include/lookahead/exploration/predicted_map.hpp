// SPDX-License-Identifier: MIT
// The look-ahead map of a mission (Chang et al. 2007, sec. II-B): every hypothesis the
// predictor made, merged in the mission map's frame, each cell with the Psi of the
// hypothesis that predicted it. Validation (model V of eq. 20): a cell is predicted only
// while the robot's map has not explored it.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/skip_rule.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

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
    const SkipRule rule =
        SkipRule::region(radius).with_min_confidence(min_confidence).with_region_tolerance(0.0).with_occupied(occupied);
    return region_area(map, cluster, rule).unpredicted;
  }
  /// The same region (within rule.region_radius, walls closing it with rule.wall_gap),
  /// split into its predicted and unpredicted parts (region_flood.hpp).
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
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) << 32) |
                                     static_cast<std::uint32_t>(c.y));
  }
  slam::OccupancyGrid cells_;
  std::unordered_map<std::int64_t, float> confidence_;
  std::size_t hypotheses_ = 0;
};

}  // namespace lookahead::exploration
