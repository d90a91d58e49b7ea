// SPDX-License-Identifier: MIT
// Matching by a separate localisation particle filter (Fairfield et al. 2010, SegSLAM sec. 4.5.2,
// SegSLAM eq. (19)). Created for one match and discarded afterwards.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <random>

#include "lookahead/slam/grid/grid_tile.hpp"
#include "lookahead/slam/rbpf/resampler.hpp"
#include "lookahead/slam/segslam/grid_submap_ops.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

// RMS distance of the window's points to the nearest obstacle, capped at the field radius.
double rms_point_error(const OccupancyGrid& map, const Pose2& pose, const Points2& cloud) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta), r = map.resolution();
  const int cap = map.distance_radius_cells() * map.distance_radius_cells();
  double sum = 0;
  for (const auto& p : cloud) {
    const int d2 = map.dist2(map.cell_at(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()));
    sum += std::min(d2, cap) * r * r;
  }
  return cloud.empty() ? INFINITY : std::sqrt(sum / static_cast<double>(cloud.size()));
}

struct Cloud {
  std::vector<Pose2> x;
  std::vector<double> logw;
};

// One measurement step: weight by the window scan seen from x (+) relative, resample, jitter.
void localization_step(Cloud& cloud, const OccupancyGrid& map, const PreparedScan& scan, const Pose2& relative,
                       const LikelihoodFieldModel& likelihood, double jitter, std::mt19937_64& rng) {
  for (std::size_t i = 0; i < cloud.x.size(); ++i) {
    cloud.logw[i] = likelihood.log_likelihood(map, cloud.x[i].compose(relative), scan);
  }
  const std::vector<std::size_t> keep = low_variance_resample(normalized_weights(cloud.logw), rng);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Pose2> next;
  for (std::size_t k : keep) {
    const Pose2& p = cloud.x[k];
    next.push_back({p.x + jitter * n(rng), p.y + jitter * n(rng), normalize_angle(p.theta + 0.2 * jitter * n(rng))});
  }
  cloud.x = std::move(next);
}

}  // namespace

WindowMatch localize_window(const OccupancyGrid& candidate, const LookaheadWindow& w, const Pose2& guess,
                            const MatchingOptions& o, const LikelihoodFieldModel& likelihood, std::uint64_t seed) {
  WindowMatch m;
  if (w.scans.empty() || w.cloud.size() < 10) return m;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  Cloud cloud;
  for (int i = 0; i < o.localization_particles; ++i) {
    cloud.x.push_back({guess.x + 0.5 * o.search_radius * n(rng), guess.y + 0.5 * o.search_radius * n(rng),
                       normalize_angle(guess.theta + 0.5 * o.search_angle * n(rng))});
  }
  cloud.logw.resize(cloud.x.size());
  // The window is short: pass over it three times with shrinking jitter (annealing).
  for (const double jitter : {0.2, 0.08, 0.03}) {
    for (std::size_t j = 0; j < w.scans.size(); ++j) {
      localization_step(cloud, candidate, w.scans[j], w.relative_poses[j], likelihood, jitter, rng);
    }
  }
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double sc = 0, ss = 0;
  for (const Pose2& p : cloud.x) mean += Eigen::Vector2d(p.x, p.y), sc += std::cos(p.theta), ss += std::sin(p.theta);
  mean /= static_cast<double>(cloud.x.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const Pose2& p : cloud.x)
    cov += (Eigen::Vector2d(p.x, p.y) - mean) * (Eigen::Vector2d(p.x, p.y) - mean).transpose();
  cov /= static_cast<double>(cloud.x.size());
  m.pose = {mean.x(), mean.y(), std::atan2(ss, sc)};
  m.icp_error = rms_point_error(candidate, m.pose, w.cloud);  // err_X
  m.translation = std::hypot(m.pose.x - guess.x, m.pose.y - guess.y);
  // p(|Sigma_X|): a cloud of one icp_sigma in both axes keeps exp(-1/2).
  m.spread_factor = std::exp(-0.5 * std::sqrt(std::max(0.0, cov.determinant())) / (o.icp_sigma * o.icp_sigma));
  m.ok = m.icp_error < o.icp_max_distance / 2;
  m.weight = m.ok ? m.spread_factor * match_weight(m.icp_error, m.translation, o) : 0.0;
  return m;
}

}  // namespace lookahead::slam::segslam
