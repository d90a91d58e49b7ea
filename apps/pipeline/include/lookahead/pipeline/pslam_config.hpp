// SPDX-License-Identifier: MIT
// The `lookahead slam --config` file of P-SLAM: the RBPF's sections (slam library) and the
// predictor's on a log (`predictor:`, `log_targets:`), each read by its own loader.
#pragma once

#include <string>

#include "lookahead/pipeline/log_prediction_config.hpp"
#include "lookahead/slam/rbpf/rbpf_options.hpp"

namespace lookahead::pipeline {

struct PslamOptions {
  slam::RbpfOptions rbpf;
  LogPredictionOptions prediction;
};

/// Both option sets from one file; an empty path gives the defaults. Errors name the file,
/// line, key and value (slam::ParseError).
PslamOptions load_pslam_options(const std::string& path);
/// What `lookahead config --dump` prints and config/slam/default.yaml holds.
std::string dump_pslam_options(const PslamOptions& options);

}  // namespace lookahead::pipeline
