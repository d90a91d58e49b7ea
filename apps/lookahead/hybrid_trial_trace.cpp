// SPDX-License-Identifier: MIT
#include "hybrid_trial_trace.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "lookahead/slam/hybrid/fastslam.hpp"
#include "lookahead/slam/hybrid/study.hpp"

namespace lookahead::app {
namespace {

using namespace slam::hybrid;
using slam::normalize_angle;
using slam::Pose2;

// Squared Mahalanobis distance of `truth` from a 2-D or 3-D Gaussian (as pose_nees).
double point_nees(const Eigen::Vector2d& truth, const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov) {
  const Eigen::Vector2d e = truth - mean;
  return e.dot((cov + 1e-9 * Eigen::Matrix2d::Identity()).ldlt().solve(e));
}

// How well the global features agree with the true ones: each against its nearest true
// feature; "bad" is beyond the 99.9 % gate of 2 dof (13.8).
struct MapScore {
  int bad = 0;
  double worst = 0.0;
};

MapScore score_map(const GlobalMap& map, const std::vector<Eigen::Vector2d>& truth) {
  MapScore s;
  for (std::size_t k = 0; k < map.features(); ++k) {
    const Eigen::Vector2d m = map.feature(k);
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector2d nearest = m;
    for (const auto& f : truth) {
      if ((f - m).squaredNorm() < best) best = (f - m).squaredNorm(), nearest = f;
    }
    const double d2 = point_nees(nearest, m, map.feature_covariance(k));
    s.bad += d2 > 13.8 ? 1 : 0;
    s.worst = std::max(s.worst, d2);
  }
  return s;
}

// Joint NEES per degree of freedom of a Gaussian map [pose, features] against the truth:
// `truth_pose` and `truth_features` in the map's own frame; each feature is scored against
// its nearest true feature when one lies within `match_radius` (clutter otherwise). The
// pose enters unless `with_pose` is false.
struct JointScore {
  double nees_per_dof = 0.0;
  int matched = 0;
};

JointScore joint_nees(const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov, const Pose2& truth_pose,
                      const std::vector<Eigen::Vector2d>& truth_features, double match_radius) {
  std::vector<Eigen::Index> rows = {0, 1, 2};
  std::vector<double> err = {truth_pose.x - mean(0), truth_pose.y - mean(1),
                             normalize_angle(truth_pose.theta - mean(2))};
  JointScore score;
  for (Eigen::Index at = 3; at + 1 < mean.size(); at += 2) {
    const Eigen::Vector2d m = mean.segment<2>(at);
    const Eigen::Vector2d* nearest = nullptr;
    for (const auto& f : truth_features) {
      if ((f - m).norm() < match_radius && (nearest == nullptr || (f - m).norm() < (*nearest - m).norm())) nearest = &f;
    }
    if (nearest == nullptr) continue;
    rows.push_back(at), rows.push_back(at + 1);
    err.push_back(nearest->x() - m.x()), err.push_back(nearest->y() - m.y());
    ++score.matched;
  }
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd p(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      p(i, j) = cov(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]);
  const Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(err.data(), n);
  p += 1e-9 * Eigen::MatrixXd::Identity(n, n);
  score.nees_per_dof = e.dot(p.ldlt().solve(e)) / static_cast<double>(n);
  return score;
}

std::vector<Eigen::Vector2d> in_frame(const Pose2& frame, const std::vector<Eigen::Vector2d>& points) {
  const Pose2 inv = frame.inverse();
  std::vector<Eigen::Vector2d> out;
  for (const auto& q : points) {
    const Pose2 t = inv.compose(Pose2{q.x(), q.y(), 0.0});
    out.emplace_back(t.x, t.y);
  }
  return out;
}

// Effective sample size of a FastSLAM front-end (0 for the EKF front-end).
double front_end_ess(const LocalFrontEnd& f) {
  const auto* fast = dynamic_cast<const FastSlam*>(&f);
  if (fast == nullptr) return 0.0;
  double sum = 0.0, sum_sq = 0.0;
  for (const auto& p : fast->particles()) sum += p.weight, sum_sq += p.weight * p.weight;
  return sum * sum / sum_sq;
}

class TraceWriter {
 public:
  TraceWriter(const std::string& path, const SimulatedRun& run) : csv_(path), run_(run), origin_(run.start) {
    if (!csv_) throw std::runtime_error("cannot write " + path);
    csv_ << "step,t,true_x,true_y,true_theta,est_x,est_y,est_theta,nees,local_nees,origin_nees,trace,"
            "fusions,local_features,associated,fusion_nis,sigma_theta,origin_sigma_theta,global_features,bad_features,"
            "worst_feature_nees,ess,"
            "observations,true_detections,local_map_nees_dof,local_map_matched,local_sigma_theta,global_map_nees_dof,"
            "global_map_matched\n";
  }

  void operator()(std::size_t i, const SubmapFilter& f) {
    const SimulatedStep& s = run_.steps[i];
    if (f.fusions() != fusions_) {  // fused at this step: the new local origin is here
      fusions_ = f.fusions();
      const GaussianMap& l = f.last_local_map();
      local_ = joint_nees(l.mean, l.covariance, origin_.between(s.truth), in_frame(origin_, run_.features), 1.0);
      local_sigma_theta_ = std::sqrt(l.covariance(2, 2));
      global_ = joint_nees(f.global_map().mean(), f.global_map().covariance(), s.truth, run_.features, 1.0);
      origin_ = s.truth;
      score_ = score_map(f.global_map(), run_.features);
    }
    const PoseGaussian v = f.vehicle();
    const PoseGaussian origin{f.global_map().origin(), f.global_map().covariance().topLeftCorner<3, 3>()};
    const Pose2& e = v.mean;
    csv_ << fmt::format(
        "{},{:.1f},{:.3f},{:.3f},{:.4f},{:.3f},{:.3f},{:.4f},{:.3f},{:.3f},{:.3f},{:.5f},{},{},{},{:.1f},{:.4f},{:.4f},"
        "{},{},{:.1f},{:.1f},{},{},{:.2f},{},{:.4f},{:.2f},{}\n",
        i, s.t, s.truth.x, s.truth.y, s.truth.theta, e.x, e.y, e.theta, pose_nees(s.truth, v),
        pose_nees(origin_.between(s.truth), f.front_end().vehicle()), pose_nees(origin_, origin), v.covariance.trace(),
        fusions_, f.last_fusion().local_features, f.last_fusion().associated, f.last_fusion().fusion_nis,
        std::sqrt(v.covariance(2, 2)), std::sqrt(origin.covariance(2, 2)), f.global_map().features(), score_.bad,
        score_.worst, front_end_ess(f.front_end()), s.observations.size(), s.true_detections, local_.nees_per_dof,
        local_.matched, local_sigma_theta_, global_.nees_per_dof, global_.matched);
  }

 private:
  std::ofstream csv_;
  const SimulatedRun& run_;
  Pose2 origin_;  ///< true pose at the last fusion: the true origin of the local map
  int fusions_ = 0;
  MapScore score_;
  JointScore local_, global_;  ///< at the last fusion: the local map handed over, the global map after
  double local_sigma_theta_ = 0.0;
};

}  // namespace

std::vector<std::string> write_trial_traces(const HybridConfig& c, int trial, const std::vector<FilterKind>& filters,
                                            const std::string& out) {
  const TrialSeeds s = trial_seeds(c.study.seed, 0, trial, c.study.worlds);
  HybridOptions o = c.filter;
  o.existence.alpha = c.study.alphas.front();
  o.existence.beta = c.study.betas.front();
  const SimulatedRun run = simulate(c.simulation, o.sensor, o.existence.alpha, o.existence.beta, s.world, s.noise);
  std::vector<std::string> lines;
  for (FilterKind k : filters) {
    const std::string path = fmt::format("{}/trial{}_{}.csv", out, trial, filter_name(k));
    TraceWriter writer(path, run);
    const TrialResult r = run_trial(k, run, o, s.filter, {c.study.failure_sigma, c.study.failure_iterations}, false,
                                    [&](std::size_t i, const SubmapFilter& f) { writer(i, f); });
    lines.push_back(fmt::format("trial {} {}: {} (failed at step {}), {} fusions, {} features -> {}", trial,
                                filter_name(k), r.success ? "success" : "failed", r.failed_at, r.fusions, r.map.size(),
                                path));
  }
  return lines;
}

}  // namespace lookahead::app
