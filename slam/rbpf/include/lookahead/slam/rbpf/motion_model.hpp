// SPDX-License-Identifier: MIT
// Odometry motion model with GMapping's noise terms (Grisetti, Stachniss, Burgard,
// "Improved techniques for grid mapping with Rao-Blackwellized particle filters",
// IEEE T-RO 2007): the odometry increment u = (dx, dy, dtheta), expressed in the frame of
// the previous pose, is perturbed by independent Gaussian noise whose standard deviations
// grow with the motion:
//   sigma_x     = srr |dx| + str |dtheta| + sxy |dy|
//   sigma_y     = srr |dy| + str |dtheta| + sxy |dx|      (sxy = 0.3 srr, as in GMapping)
//   sigma_theta = stt |dtheta| + srt sqrt(dx^2 + dy^2)
#pragma once

#include <random>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

struct MotionModelOptions {
  double srr = 0.1;  ///< translation error per metre of translation [m/m]
  double srt = 0.2;  ///< rotation error per metre of translation [rad/m]
  double str = 0.1;  ///< translation error per radian of rotation [m/rad]
  double stt = 0.2;  ///< rotation error per radian of rotation [rad/rad]
  /// Floors on the standard deviations, so a standing robot still has a proper density.
  double min_sigma_xy = 0.01;      ///< [m]
  double min_sigma_theta = 0.005;  ///< [rad]
};

class OdometryMotionModel {
 public:
  explicit OdometryMotionModel(const MotionModelOptions& options = {});

  /// Draws x_t ~ p(x_t | x_{t-1}, u).
  [[nodiscard]] Pose2 sample(const Pose2& previous, const Pose2& u, std::mt19937_64& rng) const;
  /// log p(x_t | x_{t-1}, u) up to a constant that is the same for every x_t.
  [[nodiscard]] double log_density(const Pose2& previous, const Pose2& u, const Pose2& x) const;
  /// The standard deviations of the noise on u's three components (the Gaussian filters of
  /// slam/hybrid use them as the control covariance).
  void sigmas(const Pose2& u, double& sx, double& sy, double& st) const;
  /// The standard deviation of the noise on u's rotation [rad].
  [[nodiscard]] double rotation_sigma(const Pose2& u) const;

 private:
  MotionModelOptions o_;
};

}  // namespace lookahead::slam
