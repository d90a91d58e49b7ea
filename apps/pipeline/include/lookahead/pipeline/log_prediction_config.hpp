// SPDX-License-Identifier: MIT
// YAML options of P-SLAM on a laser log (`lookahead slam --predict`): the predictor's
// options (section `predictor:`) and where and when the log replay asks for predictions
// (section `log_targets:`). They live in the same file as the RBPF's options
// (config/slam/default.yaml); each loader skips the other's sections.
#pragma once

#include <set>
#include <string>

#include "lookahead/pipeline/slam_lookahead.hpp"
#include "lookahead/predictor/predictor_options.hpp"

namespace lookahead::pipeline {

struct LogPredictionOptions {
  predictor::PredictorOptions predictor;
  SlamLookaheadOptions targets;
};

/// Reads the two sections from YAML text on top of `base`; sections named in
/// `other_sections` belong to another loader, any other unknown section or key is an error
/// naming the file, line and key (slam::ParseError).
LogPredictionOptions parse_log_prediction_options(const std::string& yaml, const std::string& source,
                                                  const LogPredictionOptions& base = {},
                                                  const std::set<std::string>& other_sections = {});
/// The sections this loader reads.
std::set<std::string> log_prediction_section_names();
/// The options as YAML with a comment per key.
std::string dump_log_prediction_options(const LogPredictionOptions& options);

}  // namespace lookahead::pipeline
