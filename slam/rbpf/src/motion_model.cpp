// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/motion_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {

OdometryMotionModel::OdometryMotionModel(const MotionModelOptions& options) : o_(options) {
  // Each message names its key, so a config error points at the line that set it.
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("motion model: ") + what);
  };
  // Upper bound: limits::kMaxMotionNoise (noise that large carries no information and
  // scatters the particles kilometres off the map).
  require(o_.srr >= 0 && o_.srr <= limits::kMaxMotionNoise, "srr in [0, 10]");
  require(o_.srt >= 0 && o_.srt <= limits::kMaxMotionNoise, "srt in [0, 10]");
  require(o_.str >= 0 && o_.str <= limits::kMaxMotionNoise, "str in [0, 10]");
  require(o_.stt >= 0 && o_.stt <= limits::kMaxMotionNoise, "stt in [0, 10]");
  require(o_.min_sigma_xy > 0 && o_.min_sigma_xy <= limits::kMaxMotionNoise, "min_sigma_xy in (0, 10]");
  require(o_.min_sigma_theta > 0 && o_.min_sigma_theta <= limits::kMaxMotionNoise, "min_sigma_theta in (0, 10]");
}

void OdometryMotionModel::sigmas(const Pose2& u, double& sx, double& sy, double& st) const {
  const double sxy = 0.3 * o_.srr;
  const double ax = std::abs(u.x), ay = std::abs(u.y), at = std::abs(u.theta);
  sx = std::max(o_.min_sigma_xy, o_.srr * ax + o_.str * at + sxy * ay);
  sy = std::max(o_.min_sigma_xy, o_.srr * ay + o_.str * at + sxy * ax);
  st = std::max(o_.min_sigma_theta, o_.stt * at + o_.srt * std::hypot(u.x, u.y));
}

double OdometryMotionModel::rotation_sigma(const Pose2& u) const {
  double sx, sy, st;
  sigmas(u, sx, sy, st);
  return st;
}

Pose2 OdometryMotionModel::sample(const Pose2& previous, const Pose2& u, std::mt19937_64& rng) const {
  double sx, sy, st;
  sigmas(u, sx, sy, st);
  std::normal_distribution<double> n(0.0, 1.0);
  const Pose2 noisy{u.x + sx * n(rng), u.y + sy * n(rng), u.theta + st * n(rng)};
  return previous.compose(noisy);
}

double OdometryMotionModel::log_density(const Pose2& previous, const Pose2& u, const Pose2& x) const {
  double sx, sy, st;
  sigmas(u, sx, sy, st);
  const Pose2 d = previous.between(x);
  const double ex = (d.x - u.x) / sx;
  const double ey = (d.y - u.y) / sy;
  const double et = normalize_angle(d.theta - u.theta) / st;
  return -0.5 * (ex * ex + ey * ey + et * et);
}

}  // namespace lookahead::slam
