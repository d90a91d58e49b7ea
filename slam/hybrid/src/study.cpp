// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/study.hpp"

#include <omp.h>

#include <stdexcept>

#include "lookahead/slam/parallel/parallel_errors.hpp"

namespace lookahead::slam::hybrid {
namespace {

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

}  // namespace

TrialSeeds trial_seeds(std::uint64_t seed, std::size_t level, int trial, int worlds) {
  const std::uint64_t t = mix(seed * 1000003ULL + level * 7919ULL + static_cast<std::uint64_t>(trial));
  // The world depends on the trial only: every clutter level sees the same 50 worlds.
  return {mix(seed + static_cast<std::uint64_t>(trial % worlds)), t, mix(t + 1)};
}

StudyResult run_study(const StudyOptions& study, const HybridOptions& filter, const SimulationOptions& sim,
                      const std::vector<FilterKind>& filters, const StudyProgress& progress) {
  if (study.alphas.size() != study.betas.size() || study.alphas.empty()) {
    throw std::invalid_argument("study: alphas and betas must have the same, non-zero length");
  }
  if (study.trials < 1 || study.worlds < 1) throw std::invalid_argument("study: trials and worlds must be >= 1");
  const std::size_t levels = study.alphas.size();
  const int jobs = static_cast<int>(levels) * study.trials;
  // outcome[job][filter]: kept per job so the sums below run in a fixed order.
  std::vector<std::vector<TrialResult>> outcome(static_cast<std::size_t>(jobs));
  const FailureRule rule{study.failure_sigma, study.failure_iterations};
  int done = 0;
  const int threads = study.threads > 0 ? study.threads : omp_get_num_procs();
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int job = 0; job < jobs; ++job) {
    errors.run([&] {
      const std::size_t level = static_cast<std::size_t>(job / study.trials);
      const int trial = job % study.trials;
      const TrialSeeds s = trial_seeds(study.seed, level, trial, study.worlds);
      HybridOptions o = filter;
      o.existence.alpha = study.alphas[level];
      o.existence.beta = study.betas[level];
      const SimulatedRun run = simulate(sim, o.sensor, o.existence.alpha, o.existence.beta, s.world, s.noise);
      auto& mine = outcome[static_cast<std::size_t>(job)];
      for (FilterKind kind : filters) {
        TrialResult r = run_trial(kind, run, o, s.filter, rule, true);
        r.trace.clear(), r.nees.clear(), r.estimate.clear(), r.map.clear();  // the table needs none
        mine.push_back(std::move(r));
      }
#pragma omp critical(hybrid_study_progress)
      {
        ++done;
        if (progress) progress(done, jobs);
      }
    });
  }
  errors.rethrow();
  StudyResult result;
  result.filters = filters;
  for (std::size_t f = 0; f < filters.size(); ++f) {
    for (std::size_t level = 0; level < levels; ++level) {
      StudyCell c{filters[f], level, 0, 0, 0.0, 0.0, {}};
      for (int trial = 0; trial < study.trials; ++trial) {
        const TrialResult& r =
            outcome[level * static_cast<std::size_t>(study.trials) + static_cast<std::size_t>(trial)][f];
        c.successes += r.success ? 1 : 0;
        if (!r.success) c.failures.emplace_back(trial, r.failed_at);
        c.trials += 1;
        c.wall_s += r.wall_s;
        c.simulated_s += r.simulated_s;
      }
      result.cells.push_back(c);
    }
  }
  return result;
}

}  // namespace lookahead::slam::hybrid
