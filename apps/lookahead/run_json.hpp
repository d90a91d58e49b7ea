// SPDX-License-Identifier: MIT
// The one writer of every command's run.json: the command's figures, plus where they come
// from (commit, CPU, threads: slam::Provenance) and the whole effective configuration.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace lookahead::app {

/// Writes DIR/run.json atomically (a reader never sees half a file). `threads` as the
/// options say it (0 = every core); `configuration_yaml` the effective options as YAML.
void write_run_json(const std::string& dir, nlohmann::json figures, int threads, const std::string& configuration_yaml);

/// YAML text indented by two spaces, to nest one dump under a key of another.
std::string indent(const std::string& yaml);

}  // namespace lookahead::app
