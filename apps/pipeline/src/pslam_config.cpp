// SPDX-License-Identifier: MIT
#include "lookahead/pipeline/pslam_config.hpp"

#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"

namespace lookahead::pipeline {

PslamOptions load_pslam_options(const std::string& path) {
  PslamOptions f;
  if (path.empty()) return f;
  const std::string text = slam::config::read_text_file(path);
  f.rbpf = slam::parse_rbpf_options(text, path, {}, log_prediction_section_names());
  f.prediction = parse_log_prediction_options(text, path, {}, slam::rbpf_section_names());
  return f;
}

std::string dump_pslam_options(const PslamOptions& options) {
  return "# lookahead slam defaults (lookahead config dump slam)\n" + slam::dump_rbpf_options(options.rbpf) +
         "# P-SLAM on a log (lookahead slam --predict): the predictor and its targets\n" +
         dump_log_prediction_options(options.prediction);
}

}  // namespace lookahead::pipeline
