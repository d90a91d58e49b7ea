// SPDX-License-Identifier: MIT
#include "moment_matching.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <map>

#include "lookahead/slam/rbpf/particle_filter.hpp"

namespace lookahead::slam::hybrid {
namespace {

double total_weight(const std::vector<Particle>& particles) {
  double w = 0.0;
  for (const auto& p : particles) w += p.weight;
  return w;
}

// Headings are averaged as deviations from a reference heading, so a cloud straddling
// +-pi averages to pi, not 0.
Eigen::Vector3d pose_vector(const Pose2& pose, double reference_heading) {
  return {pose.x, pose.y, reference_heading + normalize_angle(pose.theta - reference_heading)};
}

// Per particle, the landmark index standing for each selected common feature (-1: none).
// A particle holding several landmarks with one gamma contributes one of them, drawn at
// random (HybridSLAM sec. 3.2, first corner case).
std::vector<std::vector<int>> representatives(const std::vector<Particle>& particles, const std::vector<long>& ids,
                                              std::mt19937_64& rng) {
  std::map<long, std::size_t> column;
  for (std::size_t k = 0; k < ids.size(); ++k) column[ids[k]] = k;
  std::vector<std::vector<int>> rep(particles.size(), std::vector<int>(ids.size(), -1));
  std::vector<int> seen(ids.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    std::fill(seen.begin(), seen.end(), 0);
    const auto& lms = particles[p].landmarks;
    for (std::size_t i = 0; i < lms.size(); ++i) {
      const auto it = column.find(lms[i].id);
      if (it == column.end()) continue;
      const std::size_t k = it->second;
      // Reservoir sampling: the n-th duplicate replaces the pick with probability 1/n.
      if (++seen[k] == 1 || std::uniform_int_distribution<int>(1, seen[k])(rng) == 1) {
        rep[p][k] = static_cast<int>(i);
      }
    }
  }
  return rep;
}

}  // namespace

std::vector<CommonFeature> common_features(const std::vector<Particle>& particles) {
  const double total = total_weight(particles);
  std::map<long, CommonFeature> features;
  for (const auto& p : particles) {
    std::map<long, double> best;  // a particle counts once per feature (its likeliest copy)
    for (const auto& l : p.landmarks) {
      if (l.id < 0) continue;
      double& e = best[l.id];
      e = std::max(e, l.existence);
    }
    for (const auto& [id, e] : best) {
      CommonFeature& f = features[id];
      f.id = id;
      f.existence += p.weight * e / total;
    }
  }
  std::vector<CommonFeature> out;
  for (const auto& [id, f] : features) out.push_back(f);
  return out;
}

PoseGaussian moment_match_pose(const std::vector<Particle>& particles) {
  const double total = total_weight(particles);
  const double ref = particles[best_particle_index(particles, [](const Particle& p) { return p.weight; })].pose.theta;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : particles) mean += p.weight / total * pose_vector(p.pose, ref);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : particles) {
    const Eigen::Vector3d d = pose_vector(p.pose, ref) - mean;
    cov += p.weight / total * d * d.transpose();  // HybridSLAM eq. (7): P_vv^p = 0 for a particle
  }
  return {{mean.x(), mean.y(), normalize_angle(mean.z())}, cov};
}

GaussianMap moment_match(const std::vector<Particle>& particles, double min_existence, std::mt19937_64& rng) {
  GaussianMap g;
  for (const auto& f : common_features(particles)) {
    if (f.existence > min_existence) {
      g.ids.push_back(f.id);
      g.existence.push_back(f.existence);
    }
  }
  const std::size_t k_count = g.ids.size();
  const auto rep = representatives(particles, g.ids, rng);
  const double total = total_weight(particles);
  const Eigen::Index n = 3 + 2 * static_cast<Eigen::Index>(k_count);
  const PoseGaussian pose = moment_match_pose(particles);
  const double ref = pose.mean.theta;

  // Second corner case: a particle without feature k is ignored for it. It is given the
  // holders' mean and mean covariance instead of being dropped, which leaves the mean of k
  // unchanged, adds no spread, and keeps the covariance positive semi-definite (dropping it
  // per block would not).
  std::vector<Eigen::Vector2d> holder_mean(k_count, Eigen::Vector2d::Zero());
  std::vector<Eigen::Matrix2d> holder_cov(k_count, Eigen::Matrix2d::Zero());
  std::vector<double> holder_w(k_count, 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    for (std::size_t k = 0; k < k_count; ++k) {
      if (rep[p][k] < 0) continue;
      const Landmark& l = particles[p].landmarks[static_cast<std::size_t>(rep[p][k])];
      holder_mean[k] += particles[p].weight * l.mean;
      holder_cov[k] += particles[p].weight * l.covariance;
      holder_w[k] += particles[p].weight;
    }
  }
  for (std::size_t k = 0; k < k_count; ++k) {
    holder_mean[k] /= holder_w[k];
    holder_cov[k] /= holder_w[k];
  }

  // HybridSLAM eq. (9): each particle's stacked mean; HybridSLAM eq. (6)-(7) over them.
  std::vector<Eigen::VectorXd> x(particles.size(), Eigen::VectorXd(n));
  g.mean = Eigen::VectorXd::Zero(n);
  g.covariance = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double w = particles[p].weight / total;
    x[p].head<3>() = pose_vector(particles[p].pose, ref);
    for (std::size_t k = 0; k < k_count; ++k) {
      const Eigen::Index at = 3 + 2 * static_cast<Eigen::Index>(k);
      const int i = rep[p][k];
      const auto& lms = particles[p].landmarks;
      x[p].segment<2>(at) = i >= 0 ? lms[static_cast<std::size_t>(i)].mean : holder_mean[k];
      g.covariance.block<2, 2>(at, at) += w * (i >= 0 ? lms[static_cast<std::size_t>(i)].covariance : holder_cov[k]);
    }
    g.mean += w * x[p];
  }
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const Eigen::VectorXd d = x[p] - g.mean;
    g.covariance.selfadjointView<Eigen::Lower>().rankUpdate(d, particles[p].weight / total);
  }
  g.covariance = g.covariance.selfadjointView<Eigen::Lower>();
  g.mean(2) = normalize_angle(g.mean(2));
  return g;
}

}  // namespace lookahead::slam::hybrid
