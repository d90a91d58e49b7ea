// SPDX-License-Identifier: MIT
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/sim3d/octree_ray_cast.hpp"
#include "route_follower.hpp"

namespace lookahead::slam {
namespace {

using sim3d_detail::TrueStep;

/// IMU-and-wheel dead reckoning: integrates measured speed and yaw rate (with the gyro's
/// bias), takes roll and pitch from the IMU's gravity reference.
class DeadReckoning {
 public:
  DeadReckoning(const DeadReckoningOptions& o, const Pose3& start, std::uint64_t seed)
      : o_(o), rng_(seed), yaw_(euler_of(start.linear()).yaw), position_(start.translation()) {
    scale_ = 1.0 + std::normal_distribution<double>(0.0, o.speed_scale_sigma)(rng_);
  }
  Pose3 step(const TrueStep& truth, double dt) {
    std::normal_distribution<double> unit(0.0, 1.0);
    const double distance = truth.distance * scale_ + o_.speed_noise * dt * unit(rng_);
    yaw_ += truth.yaw_change + (o_.yaw_bias + o_.yaw_rate_noise * unit(rng_)) * dt;
    const Euler tilt = euler_of(truth.pose.linear());
    const Euler imu{tilt.roll + o_.tilt_sigma * unit(rng_), tilt.pitch + o_.tilt_sigma * unit(rng_), yaw_};
    const Pose3 pose = make_pose3(position_, imu);
    position_ += pose.linear() * Eigen::Vector3d(distance, 0.0, 0.0);
    return make_pose3(position_, imu);
  }

 private:
  DeadReckoningOptions o_;
  std::mt19937_64 rng_;
  double scale_ = 1.0;
  double yaw_;
  Eigen::Vector3d position_;
};

/// Unit beam direction in the laser frame: fan angle alpha in the plane through the
/// forward axis that the jig has turned by phi.
Eigen::Vector3d beam_direction(double alpha, double phi) {
  return {std::cos(alpha), std::sin(alpha) * std::cos(phi), std::sin(alpha) * std::sin(phi)};
}

struct Line {
  Pose3 truth, odometry;  ///< robot poses when the line was taken
  double phi = 0.0;
};

/// One sweep: cast every beam of every line in the world, then de-skew into the robot
/// frame at the sweep's end with dead reckoning.
RangeSweep make_sweep(const World3& world, const SpinningLaserOptions& o, const std::vector<Line>& lines,
                      std::mt19937_64& rng) {
  const Pose3 mount = make_pose3({0.0, 0.0, o.mount_height}, {});
  const auto beams = static_cast<std::size_t>(o.beams_per_line);
  std::vector<double> range(lines.size() * beams, -1.0);
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 4)
  for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
    errors.run([&] {
      const Pose3 laser = lines[static_cast<std::size_t>(l)].truth * mount;
      for (std::size_t b = 0; b < beams; ++b) {
        const double alpha = -M_PI / 2 + M_PI * static_cast<double>(b) / static_cast<double>(beams - 1);
        const Eigen::Vector3d dir = laser.linear() * beam_direction(alpha, lines[static_cast<std::size_t>(l)].phi);
        if (const auto r = cast_ray(world.map, laser.translation(), dir, o.max_range)) {
          range[static_cast<std::size_t>(l) * beams + b] = *r;
        }
      }
    });
  }
  errors.rethrow();
  RangeSweep sweep;
  sweep.truth = lines.back().truth;
  sweep.odometry = lines.back().odometry;
  const Pose3 end_inverse = sweep.odometry.inverse();
  std::normal_distribution<double> noise(0.0, o.range_sigma);
  for (std::size_t l = 0; l < lines.size(); ++l) {
    const Pose3 laser_in_end = end_inverse * lines[l].odometry * mount;
    for (std::size_t b = 0; b < beams; ++b) {
      const double alpha = -M_PI / 2 + M_PI * static_cast<double>(b) / static_cast<double>(beams - 1);
      const double r = range[l * beams + b];
      const bool hit = r >= 0.0;
      const double measured = hit ? std::max(0.05, r + noise(rng)) : o.max_range;
      sweep.rays.push_back(
          {laser_in_end.translation(), laser_in_end * (beam_direction(alpha, lines[l].phi) * measured), hit});
    }
  }
  return sweep;
}

}  // namespace

void CaveCrawlerOptions::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("cave crawler: ") + what);
  };
  require(speed > 0.0 && turn_rate > 0.0, "speed and turn_rate must be > 0");
  require(laser.lines_per_sweep >= 1 && laser.beams_per_line >= 2, "lines_per_sweep >= 1, beams_per_line >= 2");
  require(laser.sweep_period > 0.0 && laser.max_range > 0.0, "sweep_period and max_range must be > 0");
  require(laser.range_sigma >= 0.0, "range_sigma must be >= 0");
}

RangeLog3 simulate_cave_crawler(const World3& world, const CaveCrawlerOptions& o, std::uint64_t seed,
                                std::size_t max_sweeps, const std::function<void(std::size_t, std::size_t)>& progress) {
  o.validate();
  const double dt = o.laser.sweep_period / o.laser.lines_per_sweep;
  const std::vector<TrueStep> steps = sim3d_detail::follow_route(world.route, o.speed, o.turn_rate, dt);
  RangeLog3 log;
  log.source = world.name;
  if (steps.empty()) return log;
  std::mt19937_64 rng(seed);
  DeadReckoning dead_reckoning(o.dead_reckoning, steps.front().pose, rng());
  const auto per_sweep = static_cast<std::size_t>(o.laser.lines_per_sweep);
  std::size_t sweeps = steps.size() / per_sweep;
  if (max_sweeps > 0) sweeps = std::min(sweeps, max_sweeps);
  std::vector<Line> lines;
  for (std::size_t i = 0; i < sweeps * per_sweep; ++i) {
    const double phi = M_PI * static_cast<double>(i % per_sweep) / static_cast<double>(per_sweep);
    lines.push_back({steps[i].pose, dead_reckoning.step(steps[i], dt), phi});
    if (lines.size() < per_sweep) continue;
    log.sweeps.push_back(make_sweep(world, o.laser, lines, rng));
    log.sweeps.back().time = static_cast<double>(i + 1) * dt;
    lines.clear();
    if (progress) progress(log.sweeps.size(), sweeps);
  }
  return log;
}

}  // namespace lookahead::slam
