// SPDX-License-Identifier: MIT
#include "localization_match3.hpp"

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "lookahead/slam/rbpf/resampler.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

// The window's end points are split into this many consecutive parts (its sweeps, about:
// make_sweep_window thins them in time order), each one measurement step.
constexpr int kParts = 3;
constexpr double kHeightSigma = 0.2;  // [m]

Eigen::Vector3d apply(const Pose4& t, const Eigen::Vector3d& p) {
  const double c = std::cos(t.yaw), s = std::sin(t.yaw);
  return {t.x + c * p.x() - s * p.y(), t.y + s * p.x() + c * p.y(), t.z + p.z()};
}

// One measurement step: weigh every pose by the part's end points, resample, jitter.
void localization_step(std::vector<Pose4>& cloud, const EvidenceOctree& map, const Points3& part,
                       const OctreeLikelihoodOptions& likelihood, double jitter, std::mt19937_64& rng) {
  std::vector<double> logw(cloud.size());
  std::vector<Eigen::Vector3d> ends(part.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (std::size_t k = 0; k < part.size(); ++k) ends[k] = apply(cloud[i], part[k]);
    logw[i] = octree_log_likelihood(map, ends, likelihood);
  }
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Pose4> next;
  next.reserve(cloud.size());
  for (const std::size_t k : low_variance_resample(normalized_weights(logw), rng)) {
    const Pose4& p = cloud[k];
    // Yaw jitter as in 2D: 0.2 rad per metre of position jitter; height half the position's.
    next.push_back({p.x + jitter * n(rng), p.y + jitter * n(rng), p.z + 0.5 * jitter * n(rng),
                    normalize_angle(p.yaw + 0.2 * jitter * n(rng))});
  }
  cloud = std::move(next);
}

}  // namespace

WindowMatch3 localize_window3(const EvidenceOctree& candidate, const OctreeMatchTarget& target, const SweepWindow& w,
                              const Pose4& guess, const MatchingOptions& o, const OctreeLikelihoodOptions& likelihood,
                              const StructureTestOptions& so, std::uint64_t seed) {
  WindowMatch3 m;
  m.rejection = "too few points";
  if (target.icp.size() < 10 || w.cloud.size() < 10 || w.scored.size() < static_cast<std::size_t>(kParts)) return m;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Pose4> cloud;
  for (int i = 0; i < o.localization_particles; ++i) {
    // Height: one voxel (0.2 m) of sigma; level frames from IMU-levelled dead reckoning drift
    // little in height (the garage's z error per metre is a fifth of x and y's).
    cloud.push_back({guess.x + 0.5 * o.search_radius * n(rng), guess.y + 0.5 * o.search_radius * n(rng),
                     guess.z + kHeightSigma * n(rng), normalize_angle(guess.yaw + 0.5 * o.search_angle * n(rng))});
  }
  std::vector<Points3> parts(kParts);
  for (std::size_t k = 0; k < w.scored.size(); ++k) parts[k * kParts / w.scored.size()].push_back(w.scored[k]);
  // The window is short: three passes over it with shrinking jitter (annealing), as in 2D.
  for (const double jitter : {0.2, 0.08, 0.03}) {
    for (const Points3& part : parts) localization_step(cloud, candidate, part, likelihood, jitter, rng);
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double z = 0, sc = 0, ss = 0;
  for (const Pose4& p : cloud)
    mean += Eigen::Vector2d(p.x, p.y), z += p.z, sc += std::cos(p.yaw), ss += std::sin(p.yaw);
  mean /= static_cast<double>(cloud.size());
  z /= static_cast<double>(cloud.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Pose4& p : cloud) {
    const Eigen::Vector2d d = Eigen::Vector2d(p.x, p.y) - mean;
    cov += d * d.transpose();
  }
  cov /= static_cast<double>(cloud.size());
  const Pose4 at{mean.x(), mean.y(), z, std::atan2(ss, sc)};
  m = judge_fit(target, w, point_to_plane_fit(w.cloud, target.icp, at), guess, o, so);
  m.spread_factor = std::exp(-0.5 * std::sqrt(std::max(0.0, cov.determinant())) / (o.icp_sigma * o.icp_sigma));
  m.weight *= m.spread_factor;
  return m;
}

}  // namespace lookahead::slam::segslam
