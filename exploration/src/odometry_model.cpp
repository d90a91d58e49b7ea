// SPDX-License-Identifier: MIT
#include "lookahead/exploration/odometry_model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lookahead::exploration {

void OdometryNoiseOptions::validate() const {
  const double values[] = {srr, srt, str, stt};
  const char* names[] = {"srr", "srt", "str", "stt"};
  for (int i = 0; i < 4; ++i) {
    if (!(values[i] >= 0)) {
      throw std::invalid_argument(std::string("OdometryNoiseOptions.") + names[i] + " = " + std::to_string(values[i]) +
                                  ": must be >= 0");
    }
  }
}

OdometryModel::OdometryModel(const slam::Pose2& start, const OdometryNoiseOptions& options)
    : o_(options), pose_(start), rng_(options.seed) {
  o_.validate();
}

Eigen::Vector3d OdometryModel::sigmas(const slam::Pose2& u) const {
  const double sxy = 0.3 * o_.srr;
  const double ax = std::abs(u.x), ay = std::abs(u.y), at = std::abs(u.theta);
  return {o_.srr * ax + o_.str * at + sxy * ay, o_.srr * ay + o_.str * at + sxy * ax,
          o_.stt * at + o_.srt * std::hypot(u.x, u.y)};
}

const slam::Pose2& OdometryModel::update(const slam::Pose2& u) {
  const Eigen::Vector3d s = sigmas(u);
  std::normal_distribution<double> n(0.0, 1.0);
  // Three draws every step, even when a sigma is 0, so the stream stays aligned with the step.
  const double ex = n(rng_), ey = n(rng_), et = n(rng_);
  pose_ = pose_.compose({u.x + s.x() * ex, u.y + s.y() * ey, u.theta + s.z() * et});
  return pose_;
}

}  // namespace lookahead::exploration
