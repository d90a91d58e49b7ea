// SPDX-License-Identifier: MIT
// YAML configuration of the SLAM library: one loader for every slam option struct. Unknown
// keys and bad values are errors that name the file, the line, the key and the value.
#pragma once

#include <set>
#include <string>

#include "lookahead/slam/rbpf/rbpf_options.hpp"

namespace lookahead::slam {

/// Reads options from a YAML file on top of `base` (keys left out keep their value).
RbpfOptions load_rbpf_options(const std::string& path, const RbpfOptions& base = {});
/// Same, from YAML text (`source` names it in errors). `other_sections` are sections of
/// the same file another loader reads (the predictor's, for `lookahead slam --predict`).
RbpfOptions parse_rbpf_options(const std::string& yaml, const std::string& source, const RbpfOptions& base = {},
                               const std::set<std::string>& other_sections = {});
/// The top-level sections this loader reads.
std::set<std::string> rbpf_section_names();
/// The options as YAML, with a comment per key (what `lookahead config --dump` prints).
std::string dump_rbpf_options(const RbpfOptions& options);

}  // namespace lookahead::slam
