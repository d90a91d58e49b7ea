// SPDX-License-Identifier: MIT
// `lookahead hybrid-sim --trial N`: one trial of the study, re-run alone with a per-step
// trace that splits the failure rule's error into its local (front-end) and global
// (origin of the local map in the EKF map) parts and scores the global features against
// the true ones, to see why a trial fails.
#pragma once

#include <string>
#include <vector>

#include "lookahead/slam/hybrid/hybrid_config.hpp"
#include "lookahead/slam/hybrid/trial.hpp"

namespace lookahead::app {

/// Runs trial `trial` of the study's first clutter level with each filter and writes
/// `OUT/trial<N>_<FILTER>.csv`; returns one summary line per filter.
std::vector<std::string> write_trial_traces(const slam::hybrid::HybridConfig& config, int trial,
                                            const std::vector<slam::hybrid::FilterKind>& filters,
                                            const std::string& out);

}  // namespace lookahead::app
