// SPDX-License-Identifier: MIT
// A SICK LMS-200-like planar laser on the ground-truth raster: beams are cast cell by cell
// (Amanatides & Woo, "A fast voxel traversal algorithm for ray tracing", Eurographics 1987)
// and stop at the first occupied cell, so a range is the exact distance to that cell's edge.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <random>

#include "lookahead/exploration/world.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

struct LaserOptions {
  double fov = M_PI;                       ///< field of view [rad], (0, 2 pi]; LMS-200: 180 deg
  double angular_resolution = M_PI / 180;  ///< beam spacing [rad], > 0; LMS-200: 1, 0.5, 0.25 deg
  /// [m], > 0. 8 m is Stage's sicklaser (test_2008_sal2.world `range_max 8.0`; Shrestha et
  /// al.'s stored sick.inc, kth/SOURCES.md 6.3), the simulator P-SLAM ran on. The real
  /// LMS-200 reaches ~80 m, which would make every simulated room fully visible at once.
  double max_range = 8.0;
  /// Gaussian range noise [m], >= 0: the order of the LMS-200's centimetre-level accuracy.
  double range_sigma = 0.01;
  double rate_hz = 10.0;   ///< scans per second, > 0 (the simulator loop's clock)
  slam::Pose2 offset;      ///< laser in the robot frame; Stage's simple.world mounts it at 0
  std::uint64_t seed = 1;  ///< range-noise engine

  void validate() const;  ///< throws std::invalid_argument naming the field and value
  /// Beams from -fov/2 to +fov/2 inclusive (181 at 180/1 deg, as the LMS-200 and CARMEN's
  /// odd FLASER counts); a full circle does not repeat its first beam.
  [[nodiscard]] int beam_count() const;
  [[nodiscard]] double period() const { return 1.0 / rate_hz; }  ///< [s]
};

class LaserSimulator {
 public:
  /// Keeps a reference to `world`, which must outlive the simulator.
  explicit LaserSimulator(const World& world, const LaserOptions& options = {});

  /// One noisy scan from the robot at `true_pose`. No-returns read exactly max_range (what
  /// LaserScan::is_return() rejects); `odometry` is left for the caller to fill in.
  [[nodiscard]] slam::LaserScan scan(const slam::Pose2& true_pose, double timestamp);

  /// Noise-free distance [m] from `from` along `angle` [rad] to the first occupied cell, or
  /// +inf when nothing lies within max_range. 0 when `from` is inside an occupied cell.
  [[nodiscard]] double cast(const Eigen::Vector2d& from, double angle) const;

  [[nodiscard]] const LaserOptions& options() const { return o_; }

 private:
  const World* world_;
  LaserOptions o_;
  std::mt19937_64 rng_;
};

}  // namespace lookahead::exploration
