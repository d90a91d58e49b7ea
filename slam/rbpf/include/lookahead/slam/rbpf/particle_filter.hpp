// SPDX-License-Identifier: MIT
// The particle-filter skeleton shared by every filter with particles (the 2D and 3D RBPF,
// SegSLAM 2D and 3D, the FastSLAM front-end of HybridSLAM): normalised weights, N_eff, the
// selective resampling decision and draw, the best particle, the weighted mean pose and one
// particle's pose at every scan. Each filter keeps only its proposal, its weights and its maps.
//
// Particles are any type; the helpers read a particle's weight through `log_weight` (the RBPF
// family) or through a callable (FastSLAM keeps linear weights).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/rbpf/resampler.hpp"

namespace lookahead::slam {

/// The particles' log weights, in particle order.
template <class Particle>
std::vector<double> log_weights(const std::vector<Particle>& particles) {
  std::vector<double> logw;
  logw.reserve(particles.size());
  for (const Particle& p : particles) logw.push_back(p.log_weight);
  return logw;
}

/// Normalised weights w~_i of particles with a `log_weight` (max-shifted log-sum-exp).
template <class Particle>
std::vector<double> particle_weights(const std::vector<Particle>& particles) {
  return normalized_weights(log_weights(particles));
}

/// Subtracts the largest log weight from every log weight: the ratios, and so the normalised
/// weights, stay the same while the values stay small over a long run.
template <class Particle>
void shift_log_weights(std::vector<Particle>& particles) {
  if (particles.empty()) return;
  const double max = std::max_element(particles.begin(), particles.end(), [](const Particle& a, const Particle& b) {
                       return a.log_weight < b.log_weight;
                     })->log_weight;
  for (Particle& p : particles) p.log_weight -= max;
}

/// Selective resampling (Grisetti et al. 2007, sec. IV step 5): resample only when
/// N_eff (eq. (20)) < threshold * N.
bool should_resample(double neff, double threshold, std::size_t particles);

/// Replaces the set by the particles `keep` names (a copy shares its map by handle until it
/// writes) and gives each the weight `reset` sets.
template <class Particle, class Reset>
void draw_particles(std::vector<Particle>& particles, const std::vector<std::size_t>& keep, Reset&& reset) {
  std::vector<Particle> next;
  next.reserve(keep.size());
  for (const std::size_t k : keep) {
    next.push_back(particles[k]);
    reset(next.back());
  }
  particles = std::move(next);
}

/// Selective resampling of particles with a `log_weight` (Grisetti et al. 2007, sec. IV
/// step 5): N_eff of the normalised weights (eq. (20)); below threshold * N, a low-variance
/// draw replaces the set and every weight is reset to log 1. Returns N_eff before resampling;
/// `resampled` says whether it resampled.
template <class Particle>
double resample_if_degenerate(std::vector<Particle>& particles, double threshold, std::mt19937_64& rng,
                              bool& resampled) {
  const std::vector<double> w = particle_weights(particles);
  const double neff = effective_sample_size(w);
  resampled = should_resample(neff, threshold, particles.size());
  if (resampled) draw_particles(particles, low_variance_resample(w, rng), [](Particle& p) { p.log_weight = 0.0; });
  return neff;
}

/// Index of the particle of largest weight (`weight_of(p)`), the first one on ties.
template <class Particle, class WeightOf>
std::size_t best_particle_index(const std::vector<Particle>& particles, WeightOf&& weight_of) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < particles.size(); ++i) {
    if (weight_of(particles[i]) > weight_of(particles[best])) best = i;
  }
  return best;
}

/// Index of the particle of largest `log_weight`, the first one on ties.
template <class Particle>
std::size_t best_particle_index(const std::vector<Particle>& particles) {
  return best_particle_index(particles, [](const Particle& p) { return p.log_weight; });
}

/// Weighted mean of the planar poses `pose_of(i)` under normalised weights `w`: x and y
/// averaged, the heading as the circular mean atan2(sum w sin, sum w cos).
template <class PoseOf>
Pose2 weighted_mean_pose(const std::vector<double>& w, PoseOf&& pose_of) {
  double x = 0, y = 0, c = 0, s = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Pose2 q = pose_of(i);
    x += w[i] * q.x, y += w[i] * q.y, c += w[i] * std::cos(q.theta), s += w[i] * std::sin(q.theta);
  }
  return {x, y, std::atan2(s, c)};
}

/// Weighted mean of the positions `position_of(i)` under normalised weights `w`.
template <class PositionOf>
Eigen::Vector3d weighted_mean_position(const std::vector<double>& w, PositionOf&& position_of) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < w.size(); ++i) mean += w[i] * position_of(i);
  return mean;
}

/// Weighted mean of the level poses `pose_of(i)`: the position averaged, the yaw as the
/// circular mean atan2(sum w sin, sum w cos).
template <class PoseOf>
Pose4 weighted_mean_level_pose(const std::vector<double>& w, PoseOf&& pose_of) {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double c = 0, s = 0;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const Pose4 g = pose_of(i);
    position += w[i] * g.position();
    c += w[i] * std::cos(g.yaw), s += w[i] * std::sin(g.yaw);
  }
  return {position.x(), position.y(), position.z(), std::atan2(s, c)};
}

/// The nodes of a trajectory chain (each node links its `parent`), oldest first.
template <class Node>
std::vector<const Node*> chain_oldest_first(const Node* newest) {
  std::vector<const Node*> nodes;
  for (const Node* n = newest; n; n = n->parent.get()) nodes.push_back(n);
  return {nodes.rbegin(), nodes.rend()};
}

/// A particle's pose at every scan 0..scans-1 from its poses at the updates, (scan, pose) in
/// scan order: the latest update at or before a scan (the first update before it), moved by
/// `motion(update_scan, scan)`, the odometry between them. Empty when there is no update.
template <class Pose, class Motion>
std::vector<Pose> poses_at_every_scan(const std::vector<std::pair<std::size_t, Pose>>& updates, std::size_t scans,
                                      Motion&& motion) {
  std::vector<Pose> out;
  if (updates.empty()) return out;
  out.reserve(scans);
  std::size_t k = 0;
  for (std::size_t s = 0; s < scans; ++s) {
    while (k + 1 < updates.size() && updates[k + 1].first <= s) ++k;
    out.push_back(updates[k].second.compose(motion(updates[k].first, s)));
  }
  return out;
}

}  // namespace lookahead::slam
