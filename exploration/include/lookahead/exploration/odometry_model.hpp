// SPDX-License-Identifier: MIT
// Simulated wheel odometry that drifts the way the RBPF expects: each step's true increment
// u = (dx, dy, dtheta), in the frame of the previous pose, gets the Gaussian noise of the
// filter's motion model (slam/rbpf/motion_model.hpp, after Grisetti et al. T-RO 2007):
//   sigma_x = srr |dx| + str |dtheta| + sxy |dy|,  sigma_y = srr |dy| + str |dtheta| + sxy |dx|,
//   sigma_theta = stt |dtheta| + srt sqrt(dx^2 + dy^2),   sxy = 0.3 srr,
// and the noisy increments are chained. Deviation from the filter: no minimum sigmas, since a
// robot that stands still reads no motion from its encoders. Because noise is drawn per
// step, the drift over a path grows with sqrt(step length x path length): at 10 Hz it is
// well below what the filter assumes per 0.5 m update, as a filter's model should be.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"

namespace lookahead::exploration {

/// Defaults are the filter's own (slam::MotionModelOptions), so the filter's model is exact.
struct OdometryNoiseOptions {
  double srr = slam::MotionModelOptions{}.srr;  ///< [m/m], >= 0
  double srt = slam::MotionModelOptions{}.srt;  ///< [rad/m], >= 0
  double str = slam::MotionModelOptions{}.str;  ///< [m/rad], >= 0
  double stt = slam::MotionModelOptions{}.stt;  ///< [rad/rad], >= 0
  std::uint64_t seed = 1;

  void validate() const;  ///< throws std::invalid_argument naming the field and value
};

class OdometryModel {
 public:
  /// Odometry starts at `start` (usually the true start pose, as a real robot's zeroed
  /// encoders would be expressed in the world frame).
  explicit OdometryModel(const slam::Pose2& start, const OdometryNoiseOptions& options = {});

  /// Feeds one true increment (true_before.between(true_after)); returns the odometry pose.
  const slam::Pose2& update(const slam::Pose2& true_increment);
  [[nodiscard]] const slam::Pose2& pose() const { return pose_; }
  /// Standard deviations (x, y, theta) of the noise on increment u.
  [[nodiscard]] Eigen::Vector3d sigmas(const slam::Pose2& u) const;

 private:
  OdometryNoiseOptions o_;
  slam::Pose2 pose_;
  std::mt19937_64 rng_;
};

}  // namespace lookahead::exploration
