// SPDX-License-Identifier: MIT
// run.json of a command (slam::write_run_json, the one writer) and the YAML nesting the
// commands' configuration dumps need.
#pragma once

#include <string>

#include "lookahead/slam/io/run_json.hpp"

namespace lookahead::app {

using slam::write_run_json;

/// YAML text indented by two spaces, to nest one dump under a key of another.
std::string indent(const std::string& yaml);

}  // namespace lookahead::app
