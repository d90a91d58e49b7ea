// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/trial.hpp"

#include <Eigen/Dense>
#include <chrono>
#include <cmath>

#include "ekf_front_end.hpp"
#include "lookahead/slam/hybrid/fastslam.hpp"

namespace lookahead::slam::hybrid {

std::string filter_name(FilterKind kind) {
  switch (kind) {
    case FilterKind::kFastSlam:
      return "FASTSLAM";
    case FilterKind::kEkf:
      return "EKF";
    case FilterKind::kHybrid:
      return "HYBRID";
  }
  return "?";
}

std::unique_ptr<SubmapFilter> make_filter(FilterKind kind, const HybridOptions& options, const Pose2& start,
                                          std::uint64_t seed) {
  if (kind == FilterKind::kEkf) {
    return std::make_unique<SubmapFilter>(std::make_unique<EkfFrontEnd>(options), options, start, true);
  }
  return std::make_unique<SubmapFilter>(std::make_unique<FastSlam>(options, seed), options, start,
                                        kind != FilterKind::kFastSlam);
}

double pose_nees(const Pose2& truth, const PoseGaussian& estimate) {
  const Eigen::Vector3d e(truth.x - estimate.mean.x, truth.y - estimate.mean.y,
                          normalize_angle(truth.theta - estimate.mean.theta));
  const Eigen::Matrix3d p = estimate.covariance + 1e-9 * Eigen::Matrix3d::Identity();
  const double d2 = e.dot(p.ldlt().solve(e));
  return std::isfinite(d2) ? d2 : INFINITY;
}

TrialResult run_trial(FilterKind kind, const SimulatedRun& run, const HybridOptions& options, std::uint64_t seed,
                      const FailureRule& rule, bool stop_at_failure, const StepObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  auto filter = make_filter(kind, options, run.start, seed);
  TrialResult r;
  const double limit = rule.sigma * rule.sigma;
  int beyond = 0;
  for (std::size_t i = 0; i < run.steps.size(); ++i) {
    const SimulatedStep& s = run.steps[i];
    filter->step(s.control, s.observations);
    if (observer) observer(i, *filter);
    const PoseGaussian v = filter->vehicle();
    const double d2 = pose_nees(s.truth, v);
    r.trace.push_back(v.covariance.trace());
    r.nees.push_back(d2);
    r.estimate.push_back(v.mean);
    r.simulated_s = s.t;
    beyond = d2 > limit ? beyond + 1 : 0;
    if (beyond > rule.iterations && r.success) {
      r.success = false;
      r.failed_at = static_cast<int>(i);
      if (stop_at_failure) break;
    }
  }
  filter->finish();
  r.map = filter->feature_map();
  r.fusions = filter->fusions();
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace lookahead::slam::hybrid
