// SPDX-License-Identifier: MIT
// YAML configuration of SegSLAM (sections segmentation, matching, offline), read with the
// same machinery as the RBPF's (config/yaml_sections.hpp): unknown keys and bad values are
// errors naming the file, the line, the key and the value. The RBPF's own options stay in
// their file (config/slam/default.yaml).
#pragma once

#include <string>

#include "lookahead/slam/segslam/segslam_options.hpp"

namespace lookahead::slam {

segslam::SegSlamOptions load_segslam_options(const std::string& path, const segslam::SegSlamOptions& base = {});
segslam::SegSlamOptions parse_segslam_options(const std::string& yaml, const std::string& source,
                                              const segslam::SegSlamOptions& base = {});
/// The options as YAML with a comment per key (config/segslam/default.yaml).
std::string dump_segslam_options(const segslam::SegSlamOptions& options);

}  // namespace lookahead::slam
