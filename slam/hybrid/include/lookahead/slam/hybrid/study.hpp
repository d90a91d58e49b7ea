// SPDX-License-Identifier: MIT
// The success-rate study of HybridSLAM sec. 5.3 (Table 1): for each clutter level
// (alpha, beta) and trial, one simulated run (world = trial mod worlds) feeds every filter;
// a filter succeeds when the failure rule never fires. Trials run in parallel; every draw
// is seeded from (seed, level, trial), so results do not depend on the thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "lookahead/slam/hybrid/simulation.hpp"
#include "lookahead/slam/hybrid/trial.hpp"

namespace lookahead::slam::hybrid {

struct StudyOptions {
  /// Clutter levels (HybridSLAM sec. 5.1): p(detection) and p(false alarm) per visible feature.
  std::vector<double> alphas = {1.0, 0.7, 0.4, 0.1};
  std::vector<double> betas = {0.0, 0.02, 0.04, 0.06};
  int trials = 100;             ///< per filter and level (HybridSLAM sec. 5.3)
  int worlds = 50;              ///< distinct random worlds (HybridSLAM sec. 5.2)
  std::uint64_t seed = 1;       ///< seed of worlds, noise and filters
  int threads = 0;              ///< 0 = all cores
  double failure_sigma = 10.0;  ///< failure rule: Mahalanobis distance [std] ...
  int failure_iterations = 20;  ///< ... exceeded for more than this many iterations
};

struct StudyCell {
  FilterKind filter = FilterKind::kHybrid;
  std::size_t level = 0;
  int successes = 0;
  int trials = 0;
  double wall_s = 0.0;       ///< summed over trials
  double simulated_s = 0.0;  ///< summed over trials
  /// The failed trials (index within the level) and the step at which the rule fired, so a
  /// failure can be re-run alone (`hybrid-sim --trial`).
  std::vector<std::pair<int, int>> failures;
};

struct StudyResult {
  std::vector<StudyCell> cells;  ///< filters x levels, filter-major
  std::vector<FilterKind> filters;
};

using StudyProgress = std::function<void(int done, int total)>;

StudyResult run_study(const StudyOptions& study, const HybridOptions& filter, const SimulationOptions& sim,
                      const std::vector<FilterKind>& filters, const StudyProgress& progress = {});

/// The seeds of one trial (world, noise, filter), shared by the study and single runs.
struct TrialSeeds {
  std::uint64_t world = 0, noise = 0, filter = 0;
};
TrialSeeds trial_seeds(std::uint64_t seed, std::size_t level, int trial, int worlds);

}  // namespace lookahead::slam::hybrid
