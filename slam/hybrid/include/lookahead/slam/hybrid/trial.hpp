// SPDX-License-Identifier: MIT
// One simulated trial of one filter (HybridSLAM sec. 5): the filter runs on a simulated
// run, and the trial fails when the true pose stays more than `failure_sigma` standard
// deviations from the estimate (Mahalanobis distance under the estimated covariance) for
// more than `failure_iterations` consecutive iterations.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/simulation.hpp"
#include "lookahead/slam/hybrid/submap_filter.hpp"

namespace lookahead::slam::hybrid {

/// The filters of HybridSLAM sec. 5.1.
enum class FilterKind { kFastSlam, kEkf, kHybrid };
inline constexpr FilterKind kAllFilters[] = {FilterKind::kFastSlam, FilterKind::kEkf, FilterKind::kHybrid};
std::string filter_name(FilterKind kind);  ///< FASTSLAM, EKF, HYBRID

struct FailureRule {
  double sigma = 10.0;  ///< Mahalanobis distance of the true pose [std]
  int iterations = 20;  ///< for more than this many consecutive iterations
};

struct TrialResult {
  bool success = true;
  int failed_at = -1;        ///< step at which the rule fired
  double wall_s = 0.0;       ///< CPU-thread wall time of the filter alone [s]
  double simulated_s = 0.0;  ///< [s]
  int fusions = 0;
  std::vector<double> trace;    ///< per step: trace of the vehicle covariance
  std::vector<double> nees;     ///< per step: squared Mahalanobis distance of the truth
  std::vector<Pose2> estimate;  ///< per step
  std::vector<MapFeature> map;  ///< final feature map (global frame)
};

std::unique_ptr<SubmapFilter> make_filter(FilterKind kind, const HybridOptions& options, const Pose2& start,
                                          std::uint64_t seed);

/// Called after every step with the step index and the filter (diagnostic traces).
using StepObserver = std::function<void(std::size_t step, const SubmapFilter& filter)>;

/// Runs the whole trial; `stop_at_failure` ends it when the rule fires (studies).
TrialResult run_trial(FilterKind kind, const SimulatedRun& run, const HybridOptions& options, std::uint64_t seed,
                      const FailureRule& rule, bool stop_at_failure, const StepObserver& observer = {});

/// (true - estimate)^T P^-1 (true - estimate), heading wrapped; a tiny floor on P's diagonal
/// keeps an exactly known component (the compass heading) finite.
double pose_nees(const Pose2& truth, const PoseGaussian& estimate);

}  // namespace lookahead::slam::hybrid
