// SPDX-License-Identifier: MIT
// The similarity measurement Psi of P-SLAM (Chang et al. 2007, sec. III-B, eq. 3-5): over a
// region, twice the occupied cells the two maps share, over the occupied cells of both. Free
// cells are left out on purpose: most of a map is free, and counting them would make every
// pair of regions look alike.
//
// Deviation: a shared cell is an occupied cell of one map with an occupied cell of the other
// within `tolerance` cells (counted from both sides, so Psi stays in [0, 1]); with tolerance
// 0 this is eq. 5 exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::predictor {

/// A coarse raster of a grid for Psi: a cell is occupied when any fine cell in it is, known
/// when any fine cell in it is. Row-major, cell (0, 0) at `origin`.
class CoarseOccupancy {
 public:
  CoarseOccupancy(const slam::OccupancyGrid& grid, double resolution, double occupied_threshold, int tolerance_cells);
  [[nodiscard]] double resolution() const { return res_; }
  [[nodiscard]] bool occupied(double x, double y) const { return flags(x, y) & kOccupied; }
  /// An occupied cell within the tolerance of (x, y).
  [[nodiscard]] bool near_occupied(double x, double y) const { return flags(x, y) & kNearOccupied; }
  [[nodiscard]] bool known(double x, double y) const { return flags(x, y) & kKnown; }
  /// The three at once (bits kOccupied, kNearOccupied, kKnown; 0 outside): Psi reads every
  /// cell of a region for each of hundreds of alignments, one read each.
  [[nodiscard]] std::uint8_t flags(double x, double y) const;
  static constexpr std::uint8_t kOccupied = 1, kNearOccupied = 2, kKnown = 4;

 private:
  double res_ = 0.1, x0_ = 0, y0_ = 0;
  int w_ = 0, h_ = 0;
  std::vector<std::uint8_t> cells_;
};

/// Sample points of a disc region: centres of the coarse cells within `diameter` / 2 of
/// (cx, cy).
struct RegionSamples {
  std::vector<double> x, y;
};
RegionSamples disc_samples(double cx, double cy, double diameter, double resolution);

struct SimilarityScore {
  double psi = 0.0;            ///< eq. 5 (with the tolerance above)
  int target_occupied = 0;     ///< sum J(S_f)
  int reference_occupied = 0;  ///< sum J(C)
  int new_known = 0;           ///< samples unknown in the target but known in the reference
  /// Walls of one map on cells the other has explored as free (no wall within the
  /// tolerance): evidence against the alignment that eq. 5, counting occupied cells only,
  /// cannot see.
  int conflicts = 0;
  [[nodiscard]] double conflict_share() const {
    const int total = target_occupied + reference_occupied;
    return total > 0 ? static_cast<double>(conflicts) / total : 0.0;
  }
};

/// Psi between the target region (samples in the map frame) and the reference region
/// brought onto it by `reference_to_target` (p_target = T (+) p_reference).
SimilarityScore similarity(const CoarseOccupancy& target_map, const CoarseOccupancy& reference_map,
                           const RegionSamples& region, const slam::Pose2& reference_to_target);

/// A target region with its cells read once: a registration scores hundreds of alignments
/// of one region.
struct TargetRegion {
  TargetRegion(const CoarseOccupancy& target_map, RegionSamples samples);
  RegionSamples samples;
  std::vector<std::uint8_t> flags;  ///< target_map.flags() of each sample
};
SimilarityScore similarity(const TargetRegion& target, const CoarseOccupancy& reference_map,
                           const slam::Pose2& reference_to_target);

}  // namespace lookahead::predictor
