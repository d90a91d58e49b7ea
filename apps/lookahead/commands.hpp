// SPDX-License-Identifier: MIT
// The subcommands of `lookahead`: each registers its options and returns the function that
// runs it. Parsing stays here; the work is in the libraries.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace lookahead::app {

using Run = std::function<int()>;

Run add_slam_command(CLI::App& app);
Run add_slam3d_command(CLI::App& app);
Run add_eval_command(CLI::App& app);
Run add_check_command(CLI::App& app);
Run add_config_command(CLI::App& app);
Run add_explore_command(CLI::App& app);
Run add_study_command(CLI::App& app);
Run add_predict_command(CLI::App& app);
Run add_hybrid_sim_command(CLI::App& app);

}  // namespace lookahead::app
