// SPDX-License-Identifier: MIT
#include "lookahead/pipeline/log_prediction_config.hpp"

#include <stdexcept>

#include "lookahead/predictor/predictor_keys.hpp"
#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::pipeline {
namespace {

template <typename V>
void visit_sections(LogPredictionOptions& o, V&& v) {
  v.section("predictor");
  predictor::visit_predictor_keys(o.predictor, v);
  v.section("log_targets");
  SlamLookaheadOptions& t = o.targets;
  v("period_updates", t.period_updates, "a new prediction request every this many filter updates");
  v("latency_updates", t.latency_updates, "a prediction reaches the filter this many updates later");
  v("range", t.range, "targets: frontier cells up to this far from the robot [m]");
  v("half_angle", t.half_angle, "... and within this of its heading [rad]");
  v("max_candidates", t.max_candidates, "frontier cells offered per request, nearest first");
  v("candidate_spacing", t.candidate_spacing, "... at least this far apart [m]");
  v("wait_for_predictions", t.wait_for_predictions,
    "the replay waits for a late prediction (false: takes it at a later update, as a live robot)");
}

void validate_targets(const SlamLookaheadOptions& t) {
  if (t.period_updates < 1) throw std::invalid_argument("log_targets.period_updates >= 1");
  if (t.latency_updates < 0) throw std::invalid_argument("log_targets.latency_updates >= 0");
  if (!(t.range > 0)) throw std::invalid_argument("log_targets.range > 0");
  if (!(t.half_angle > 0)) throw std::invalid_argument("log_targets.half_angle > 0");
  if (t.max_candidates < 1) throw std::invalid_argument("log_targets.max_candidates >= 1");
  if (!(t.candidate_spacing >= 0)) throw std::invalid_argument("log_targets.candidate_spacing >= 0");
}

}  // namespace

LogPredictionOptions parse_log_prediction_options(const std::string& yaml, const std::string& source,
                                                  const LogPredictionOptions& base,
                                                  const std::set<std::string>& other_sections) {
  return slam::config::parse_options(
      yaml, source, base, [](LogPredictionOptions& o, auto& v) { visit_sections(o, v); },
      [](const LogPredictionOptions& o) {
        validate(o.predictor);
        validate_targets(o.targets);
      },
      other_sections);
}

std::set<std::string> log_prediction_section_names() {
  slam::config::SectionNames names;
  LogPredictionOptions o;
  visit_sections(o, names);
  return names.names;
}

std::string dump_log_prediction_options(const LogPredictionOptions& options) {
  return slam::config::dump_options(options, [](LogPredictionOptions& o, auto& v) { visit_sections(o, v); });
}

}  // namespace lookahead::pipeline
