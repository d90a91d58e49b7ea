// SPDX-License-Identifier: MIT
// Point landmarks from a 2D laser scan for HybridSLAM on real logs: corners (two straight
// segments meeting at a clear angle) and line ends (a segment whose end is not occluded:
// the next beam returns far behind it, or not at all). Segments come from split-and-merge
// on runs of consecutive beams (Nguyen et al., "A comparison of line extraction algorithms
// using 2D laser rangefinder", IROS 2005, "split-and-merge").
//
// Covariance (documented model, robot frame): a corner is the intersection of two fitted
// lines, isotropic with std corner_sigma; a line end is known across its line to
// end_sigma_across, and along it only to end_sigma_along plus the gap to the next beam
// (range x angular step), since the true end lies somewhere before that beam.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/hybrid/range_bearing.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam::hybrid {

/// Defaults and units are documented in config/hybrid/default.yaml (section scan_landmarks).
struct ScanLandmarkOptions {
  double max_range = 15.0;                       ///< beams used up to [m]
  double break_distance = 0.25;                  ///< a run breaks where consecutive points are farther [m] (+ 3 r dphi)
  double split_tolerance = 0.04;                 ///< split a run where a point is this far from the chord [m]
  int min_points = 8;                            ///< beams per segment
  double min_length = 0.6;                       ///< segment length [m]
  double corner_min_angle = 1.0471975511965976;  ///< 60 deg: lines meet at least this sharply
  double corner_max_gap = 0.15;                  ///< the intersection lies this close to the shared beam [m]
  double occlusion_margin = 0.5;                 ///< a neighbour this much farther (or missing) leaves the end free [m]
  /// ... unless it lies this close to the segment's line (the wall goes on) [m]
  double continuation_distance = 0.0;
  double min_incidence = 0.0;      ///< a line end's beam meets its line at least this steeply [rad]
  bool line_ends = true;           ///< report free line ends (else corners only)
  double corner_sigma = 0.05;      ///< [m]
  double end_sigma_across = 0.05;  ///< [m]
  double end_sigma_along = 0.10;   ///< [m] (plus the beam gap)
};

/// Throws std::invalid_argument naming the first impossible option.
void validate(const ScanLandmarkOptions& options);

struct ScanLandmark {
  enum class Kind { kCorner, kLineEnd };
  Kind kind = Kind::kCorner;
  Eigen::Vector2d point;       ///< robot frame [m]
  Eigen::Matrix2d covariance;  ///< robot frame [m^2]
};

std::vector<ScanLandmark> extract_scan_landmarks(const LaserScan& scan, const ScanLandmarkOptions& options);

/// The landmark as a range-bearing observation from the robot, its covariance carried over
/// by the Jacobian of (x, y) -> (r, b).
RangeBearing to_observation(const ScanLandmark& landmark);

}  // namespace lookahead::slam::hybrid
