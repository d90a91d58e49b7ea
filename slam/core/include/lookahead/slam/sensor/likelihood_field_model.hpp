// SPDX-License-Identifier: MIT
// Likelihood-field ("end point") model of a laser scan against an occupancy grid
// (Thrun, Burgard, Fox, Probabilistic Robotics, sec. 6.4): each beam end point scores by
// its distance to the nearest obstacle, read from the grid's distance field in O(1).
#pragma once

#include <array>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam {

struct LikelihoodOptions {
  double sigma = 0.05;         ///< std. dev. of an end point around the wall it hit [m]
  double random_floor = 0.05;  ///< mixture weight of unexplained readings, (0, 1)
  /// Likelihood of an end point in never-observed space: neither evidence for nor against.
  double unknown_likelihood = 0.3;
  int beam_step = 2;        ///< use every n-th beam (neighbouring beams are correlated)
  double max_range = 30.0;  ///< longer readings are left out of the likelihood [m]
  /// Exponent on the product over beams (GMapping's "gain"): the beams are not independent,
  /// and the plain product is far too peaked for a particle filter. 1 = plain product.
  double temperature = 0.3;
};

/// How an end point reads the distance field: the value of the cell it falls in, or the
/// bilinear blend of the four cell centres around it (sub-cell precision, four reads).
enum class FieldLookup { kCell, kBilinear };

/// A scan reduced to the beam end points the model uses, in the laser frame.
struct PreparedScan {
  std::vector<float> x, y;
  Pose2 laser_offset;
};

PreparedScan prepare_scan(const LaserScan& scan, const LikelihoodOptions& options);

class LikelihoodFieldModel {
 public:
  LikelihoodFieldModel(const LikelihoodOptions& options, const OccupancyGrid& like_grid);

  /// Tempered log p(z | x, m) of the scan from robot pose `robot` on `grid`.
  [[nodiscard]] double log_likelihood(const OccupancyGrid& grid, const Pose2& robot, const PreparedScan& scan,
                                      FieldLookup lookup = FieldLookup::kCell) const;
  /// Share of end points within one sigma-ish of an obstacle (a match-quality figure).
  [[nodiscard]] double hit_ratio(const OccupancyGrid& grid, const Pose2& robot, const PreparedScan& scan) const;
  /// Tempered log-likelihood of one end point at world (wx, wy) on `grid`; `hit` tells
  /// whether it lies within the hit distance of an obstacle (P-SLAM's z_u scoring).
  [[nodiscard]] double end_point_log_likelihood(const OccupancyGrid& grid, double wx, double wy, bool& hit) const;
  [[nodiscard]] const LikelihoodOptions& options() const { return options_; }
  /// Squared cell distance up to which hit_ratio counts an end point as a hit [cells^2].
  [[nodiscard]] int hit_dist2() const { return hit_dist2_; }

 private:
  LikelihoodOptions options_;
  [[nodiscard]] double cell_log_likelihood(const OccupancyGrid& grid, int cx, int cy) const;
  [[nodiscard]] double bilinear_log_likelihood(const OccupancyGrid& grid, const Pose2& laser,
                                               const PreparedScan& scan) const;

  std::array<double, 256> log_by_dist2_{};  // indexed by squared cell distance
  double log_unknown_ = 0.0;
  int hit_dist2_ = 0;
};

}  // namespace lookahead::slam
