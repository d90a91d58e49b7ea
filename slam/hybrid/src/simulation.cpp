// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace lookahead::slam::hybrid {
namespace {

// Waypoints near the border, counter-clockwise from the middle of the bottom side: the four
// corners and two points per side, each pulled inwards at random.
std::vector<Eigen::Vector2d> loop_waypoints(const SimulationOptions& o, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> jitter(0.0, o.inset_jitter);
  const double lo = o.inset, hi = o.world_size - o.inset, mid = o.world_size / 2;
  const std::vector<Eigen::Vector2d> corners = {{hi, lo}, {hi, hi}, {lo, hi}, {lo, lo}};
  std::vector<Eigen::Vector2d> w;
  Eigen::Vector2d from(mid, lo);
  for (const auto& c : corners) {
    const Eigen::Vector2d inward = (Eigen::Vector2d(mid, mid) - c).normalized();
    for (double f : {0.35, 0.7}) {
      const Eigen::Vector2d p = from + f * (c - from);
      w.push_back(p + jitter(rng) * (Eigen::Vector2d(mid, mid) - p).normalized());
    }
    w.push_back(c + jitter(rng) * inward);
    from = c;
  }
  w.emplace_back(mid, lo);
  w.emplace_back(mid + o.loop_overlap, lo);  // past the start: the loop must close
  return w;
}

RangeBearing observe_point(const Pose2& pose, const Eigen::Vector2d& p, const SensorOptions& s,
                           std::normal_distribution<double>& n, std::mt19937_64& rng) {
  const double dx = p.x() - pose.x, dy = p.y() - pose.y;
  return {std::hypot(dx, dy) + s.sigma_range * n(rng),
          normalize_angle(std::atan2(dy, dx) - pose.theta + s.sigma_bearing * n(rng)),
          range_bearing_noise(s.sigma_range, s.sigma_bearing)};
}

std::vector<RangeBearing> sense(const Pose2& pose, const std::vector<Eigen::Vector2d>& features, const SensorOptions& s,
                                double alpha, double beta, std::mt19937_64& rng, int& detections) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<RangeBearing> z;
  detections = 0;
  for (const auto& f : features) {
    if (std::hypot(f.x() - pose.x, f.y() - pose.y) > s.max_range) continue;
    if (u(rng) < alpha) {
      z.push_back(observe_point(pose, f, s, n, rng));
      ++detections;
    }
    if (u(rng) < beta) {  // a false alarm at a uniform range and bearing
      z.push_back({u(rng) * s.max_range, normalize_angle(2.0 * M_PI * u(rng)),
                   range_bearing_noise(s.sigma_range, s.sigma_bearing)});
    }
  }
  std::shuffle(z.begin(), z.end(), rng);  // the filters must not rely on the order
  return z;
}

}  // namespace

SimulatedRun simulate(const SimulationOptions& o, const SensorOptions& sensor, double alpha, double beta,
                      std::uint64_t world_seed, std::uint64_t noise_seed) {
  std::mt19937_64 world_rng(world_seed * 0x9E3779B97F4A7C15ULL + 7);
  std::mt19937_64 rng(noise_seed * 0xBF58476D1CE4E5B9ULL + 13);
  SimulatedRun run;
  std::uniform_real_distribution<double> coord(0.0, o.world_size);
  for (int i = 0; i < o.features; ++i) run.features.emplace_back(coord(world_rng), coord(world_rng));
  run.waypoints = loop_waypoints(o, world_rng);
  run.start = {o.world_size / 2, o.inset, 0.0};
  std::normal_distribution<double> n(0.0, 1.0);
  Pose2 truth = run.start;
  double t = 0.0;
  const std::size_t max_steps = static_cast<std::size_t>(4.0 * o.world_size * 4.0 / (o.speed * o.dt));
  for (std::size_t w = 0; w < run.waypoints.size() && run.steps.size() < max_steps;) {
    const Eigen::Vector2d to = run.waypoints[w] - Eigen::Vector2d(truth.x, truth.y);
    if (to.norm() < 1.0) {
      ++w;
      continue;
    }
    const double error = normalize_angle(std::atan2(to.y(), to.x()) - truth.theta);
    const double omega = std::clamp(o.steering_gain * error, -o.max_turn_rate, o.max_turn_rate);
    SimulatedStep s;
    const double turn_sigma = o.compass ? 0.0 : o.turn_noise * std::abs(omega);
    s.control.delta = {o.speed * o.dt, 0.0, omega * o.dt};
    s.control.sigma = {o.velocity_noise * o.speed * o.dt, 0.0, turn_sigma * o.dt};
    s.control.dt = o.dt;
    // The true vehicle executes the commanded velocities plus noise; the filters get the
    // commands and the noise model.
    const double v_true = o.speed + o.velocity_noise * o.speed * n(rng);
    const double w_true = omega + turn_sigma * n(rng);
    truth = truth.compose({v_true * o.dt, 0.0, w_true * o.dt});
    run.path_length += std::abs(v_true) * o.dt;
    t += o.dt;
    s.t = t;
    s.truth = truth;
    s.observations = sense(truth, run.features, sensor, alpha, beta, rng, s.true_detections);
    run.steps.push_back(std::move(s));
  }
  return run;
}

}  // namespace lookahead::slam::hybrid
