// SPDX-License-Identifier: MIT
// Every parameter of the grid RBPF, nested by component. The defaults here are the only
// copy; config/slam/default.yaml is checked against them by a test.
#pragma once

#include <cstdint>

#include "lookahead/slam/grid/grid_options.hpp"
#include "lookahead/slam/grid/hypothesis.hpp"
#include "lookahead/slam/rbpf/improved_proposal.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/rbpf/scan_matcher.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::slam {

struct RbpfOptions {
  int particles = 30;               ///< N, 1..100000
  std::uint64_t seed = 1;           ///< every random draw derives from it
  int threads = 0;                  ///< worker threads for the particle loop; 0 = all cores
  double linear_update = 0.5;       ///< filter update after this much travel [m]
  double angular_update = 0.25;     ///< ... or this much rotation [rad]
  double resample_threshold = 0.5;  ///< resample when N_eff < threshold * N (0..1]
  /// Updates during which scans are only inserted, before matching starts: the first scans
  /// have no map worth matching against.
  int warmup_updates = 1;
  /// Exponent k on the weight factor: w_t = w_{t-1} eta^k. Deviation from Grisetti et al.
  /// (k = 1): the likelihood of correlated beams is overconfident, weights degenerate after
  /// a few updates and the resampling that follows wipes out the particles a later loop
  /// closure needs. GMapping flattens its weights for the same reason (its "ogain").
  /// Measured: k = 1 left a doubled corridor in 2 of 6 Intel/fr079 runs, k = 0.3 in none.
  double weight_exponent = 0.3;
  GridOptions grid;
  InsertOptions insert;
  MotionModelOptions motion;
  LikelihoodOptions likelihood;
  ScanMatcherOptions matcher;
  ProposalOptions proposal;
  PredictionOptions prediction;  ///< P-SLAM: hypotheses in the weights (off by default)
};

}  // namespace lookahead::slam
