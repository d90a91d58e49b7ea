// SPDX-License-Identifier: MIT
#include "lookahead/exploration/laser_simulator.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::exploration {
namespace {

void require(bool ok, const char* field, double value, const char* why) {
  if (!ok) {
    throw std::invalid_argument(std::string("LaserOptions.") + field + " = " + std::to_string(value) + ": " + why);
  }
}

// Distance (in cells, along the ray) to the first grid line crossed on one axis, and the
// distance between crossings.
void axis_setup(double g, double d, int& step, double& t_next, double& t_delta) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (d > 0) {
    step = 1;
    t_next = (std::floor(g) + 1.0 - g) / d;
    t_delta = 1.0 / d;
  } else if (d < 0) {
    step = -1;
    t_next = (g - std::floor(g)) / -d;
    t_delta = -1.0 / d;
  } else {
    step = 0;
    t_next = kInf;
    t_delta = kInf;
  }
}

}  // namespace

void LaserOptions::validate() const {
  require(fov > 0 && fov <= 2 * M_PI + 1e-9, "fov", fov, "must be in (0, 2 pi]");
  require(angular_resolution > 0 && angular_resolution <= fov, "angular_resolution", angular_resolution,
          "must be in (0, fov]");
  require(max_range > 0 && max_range <= slam::limits::kMaxLaserRange, "max_range", max_range,
          "must be in (0, 1000] m (limits::kMaxLaserRange)");
  require(fov / angular_resolution <= static_cast<double>(slam::limits::kMaxBeams), "angular_resolution",
          angular_resolution, "gives over 100000 beams per scan (limits::kMaxBeams)");
  require(range_sigma >= 0, "range_sigma", range_sigma, "must be >= 0");
  require(rate_hz > 0, "rate_hz", rate_hz, "must be > 0");
}

int LaserOptions::beam_count() const {
  const int gaps = static_cast<int>(std::lround(fov / angular_resolution));
  return fov >= 2 * M_PI - 1e-9 ? gaps : gaps + 1;
}

LaserSimulator::LaserSimulator(const World& world, const LaserOptions& options)
    : world_(&world), o_(options), rng_(options.seed) {
  o_.validate();
}

double LaserSimulator::cast(const Eigen::Vector2d& from, double angle) const {
  const double res = world_->resolution();
  const Eigen::Vector2d g = (from - world_->origin()) / res;  // grid units
  const double dx = std::cos(angle), dy = std::sin(angle);
  slam::CellIndex c{static_cast<int>(std::floor(g.x())), static_cast<int>(std::floor(g.y()))};
  if (world_->is_occupied(c)) return 0.0;
  int sx, sy;
  double tx, ty, ddx, ddy;
  axis_setup(g.x(), dx, sx, tx, ddx);
  axis_setup(g.y(), dy, sy, ty, ddy);
  const double t_max = o_.max_range / res;
  while (true) {
    // Step into the neighbour whose boundary the ray reaches first; t is where it enters.
    double t;
    if (tx < ty) {
      t = tx;
      tx += ddx;
      c.x += sx;
    } else {
      t = ty;
      ty += ddy;
      c.y += sy;
    }
    if (t > t_max) return std::numeric_limits<double>::infinity();
    if (world_->is_occupied(c)) return t * res;
  }
}

slam::LaserScan LaserSimulator::scan(const slam::Pose2& true_pose, double timestamp) {
  slam::LaserScan s;
  s.timestamp = timestamp;
  s.logger_timestamp = timestamp;
  s.laser_offset = o_.offset;
  s.max_range = o_.max_range;
  const int n = o_.beam_count();
  s.angle_min = -o_.fov / 2.0;
  s.angle_increment = o_.angular_resolution;
  s.ranges.resize(static_cast<std::size_t>(n));
  const slam::Pose2 laser = true_pose.compose(o_.offset);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double r = cast({laser.x, laser.y}, laser.theta + s.bearing(static_cast<std::size_t>(i)));
    // Draw for every beam, so one beam's outcome does not shift the next beams' noise.
    const double e = o_.range_sigma * noise(rng_);
    const double noisy = std::max(0.0, r + e);
    s.ranges[static_cast<std::size_t>(i)] =
        static_cast<float>(std::isfinite(r) && noisy < o_.max_range ? noisy : o_.max_range);
  }
  return s;
}

}  // namespace lookahead::exploration
