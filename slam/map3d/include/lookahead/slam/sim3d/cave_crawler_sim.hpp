// SPDX-License-Identifier: MIT
// A simulated Cave Crawler (SegSLAM sec. 5.1): a 2D laser on a jig that spins about the
// robot's forward axis, IMU-and-wheel dead reckoning whose gyro has a yaw bias (the
// largest error source the paper names), and continuous motion: the robot does not stop
// to scan, so each sweep is de-skewed with dead reckoning.
#pragma once

#include <cstdint>
#include <functional>

#include "lookahead/slam/sensor/range_sweep.hpp"
#include "lookahead/slam/sim3d/world3d.hpp"

namespace lookahead::slam {

struct SpinningLaserOptions {
  /// Fan: a 180 deg 2D scan whose plane contains the forward axis; the jig turns that
  /// plane about the forward axis, so one half turn covers the forward hemisphere.
  int lines_per_sweep = 30;   ///< 2D scans per half turn (6 deg of spin apart), >= 1
  int beams_per_line = 61;    ///< beams across the fan (3 deg apart), >= 2
  double sweep_period = 1.0;  ///< half-turn time [s], > 0
  double max_range = 30.0;    ///< no return beyond [m], > 0
  double range_sigma = 0.02;  ///< range noise std [m], >= 0
  double mount_height = 0.6;  ///< laser above the robot's base [m]
};

struct DeadReckoningOptions {
  double speed_scale_sigma = 0.01;  ///< wheel-odometry scale error, drawn once per run
  double speed_noise = 0.02;        ///< white noise on the speed [m/s]
  double yaw_bias = 0.0015;         ///< gyro bias [rad/s] (0.086 deg/s)
  double yaw_rate_noise = 0.003;    ///< white noise on the yaw rate [rad/s]
  double tilt_sigma = 0.003;        ///< IMU roll and pitch noise [rad] (gravity-referenced)
};

struct CaveCrawlerOptions {
  double speed = 1.0;      ///< driving speed [m/s], > 0
  double turn_rate = 0.5;  ///< turning on the spot at corners [rad/s], > 0
  SpinningLaserOptions laser;
  DeadReckoningOptions dead_reckoning;

  void validate() const;
};

/// Drives the world's route once; one sweep per half turn of the laser. Same seed, same
/// log. Stops after `max_sweeps` sweeps when it is not 0. `progress(done, total)` is
/// called after each sweep.
RangeLog3 simulate_cave_crawler(const World3& world, const CaveCrawlerOptions& options, std::uint64_t seed,
                                std::size_t max_sweeps = 0,
                                const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace lookahead::slam
