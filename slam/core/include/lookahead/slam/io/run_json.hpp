// SPDX-License-Identifier: MIT
// The one writer of every run folder's run.json (each subcommand's and each mission's): the
// run's figures, plus where they come from (commit, CPU, threads: Provenance) and the whole
// effective configuration, so a run can be repeated from its folder alone.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace lookahead::slam {

/// Writes DIR/run.json atomically (a reader never sees half a file). `threads` as the
/// options say it (0 = every core); `configuration_yaml` the effective options as YAML.
void write_run_json(const std::string& dir, nlohmann::json figures, int threads, const std::string& configuration_yaml);

}  // namespace lookahead::slam
