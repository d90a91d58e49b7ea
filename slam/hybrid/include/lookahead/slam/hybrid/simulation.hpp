// SPDX-License-Identifier: MIT
// The simulated experiment of HybridSLAM sec. 5.2: random 120 m x 120 m worlds with 35
// uniformly placed point features; a vehicle at 1 m/s and up to 100 deg/s on a path near
// the extremities that closes one loop of about 400 m; a 360 deg range-bearing sensor
// (25 m, 10 Hz, 0.05 m and 1 deg) with detection probability alpha and, per visible
// feature, a false alarm with probability beta at a uniform range and bearing; velocity
// noise 0.25 v and 0.35 omega. Identical data feed every filter.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/motion_step.hpp"
#include "lookahead/slam/hybrid/range_bearing.hpp"

namespace lookahead::slam::hybrid {

struct SimulationOptions {
  double world_size = 120.0;                  ///< side of the square world [m]
  int features = 35;                          ///< uniformly placed point features
  double speed = 1.0;                         ///< commanded linear velocity [m/s]
  double max_turn_rate = 1.7453292519943295;  ///< [rad/s] (100 deg/s)
  double steering_gain = 3.0;                 ///< turn rate per radian of heading error [1/s]
  double dt = 0.1;                            ///< control and observation period [s] (10 Hz)
  double inset = 12.0;                        ///< the loop runs this far inside the border [m]
  double inset_jitter = 6.0;                  ///< waypoints move up to this far, randomly [m]
  double loop_overlap = 30.0;                 ///< travel past the start after the loop [m]
  double velocity_noise = 0.25;               ///< std of v as a fraction of v
  double turn_noise = 0.35;                   ///< std of omega as a fraction of omega
  /// Fig. 3: an accurate compass. Deviation: modelled as a heading known exactly (no
  /// turn-rate noise), which is what "eliminating vehicle linearisation errors" needs.
  bool compass = false;
};

struct SimulatedStep {
  double t = 0.0;                          ///< [s]
  Pose2 truth;                             ///< true pose after the step
  MotionStep control;                      ///< commanded motion with its noise model
  std::vector<RangeBearing> observations;  ///< at the true pose, clutter included
  int true_detections = 0;
};

struct SimulatedRun {
  std::vector<Eigen::Vector2d> features;
  std::vector<Eigen::Vector2d> waypoints;
  Pose2 start;
  std::vector<SimulatedStep> steps;
  double path_length = 0.0;  ///< [m]
};

/// World `world_seed` (features and path), noise and clutter from `noise_seed`.
SimulatedRun simulate(const SimulationOptions& sim, const SensorOptions& sensor, double alpha, double beta,
                      std::uint64_t world_seed, std::uint64_t noise_seed);

}  // namespace lookahead::slam::hybrid
