// SPDX-License-Identifier: MIT
// YAML configuration of an exploration mission: the one loader of the exploration library.
// Sections mission, robot, laser, odometry, planner, follower, frontiers, blacklist and slam
// (the last in the config/slam format, read by slam::parse_rbpf_options). Keys left out keep
// their value; unknown keys, bad values and impossible combinations are slam::ParseError
// naming the file, the line, the key and the value. config/mission/default.yaml is
// dump_mission_options(MissionOptions::defaults()), and a test keeps it so.
#pragma once

#include <optional>
#include <string>

#include "lookahead/exploration/mission_options.hpp"

namespace lookahead::exploration {

/// Reads options from a YAML file on top of `base`, then harmonize() and validate().
MissionOptions load_mission_options(const std::string& path, const MissionOptions& base = MissionOptions::defaults());
/// Same, from YAML text (`source` names it in errors).
MissionOptions parse_mission_options(const std::string& yaml, const std::string& source,
                                     const MissionOptions& base = MissionOptions::defaults());
/// The options as YAML with a comment per key (what config/mission/default.yaml holds).
std::string dump_mission_options(const MissionOptions& options);

/// "slam" | "truth", and back (nullopt for any other text).
const char* pose_source_name(PoseSource source);
std::optional<PoseSource> pose_source_from_name(const std::string& name);

/// The text of a block-style YAML map nested in `text` whose first key yaml-cpp marks at
/// (line, column), both 0-based: its lines dedented by `column`, preceded by `line` empty
/// lines so that a parser of the result reports the line numbers of `text`. The block ends
/// at the first line that is indented less than `column` and is not blank or a comment.
std::string yaml_block_text(const std::string& text, int line, int column);

}  // namespace lookahead::exploration
