// SPDX-License-Identifier: MIT
// `lookahead config --dump`: the documented defaults, the source of config/slam/default.yaml.
#include <fmt/format.h>

#include "commands.hpp"
#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/predictor/pslam_config.hpp"

namespace lookahead::app {

Run add_config_command(CLI::App& app) {
  auto check = std::make_shared<std::string>();
  app.add_flag("--dump", "print the default SLAM configuration (YAML)");
  auto mission = std::make_shared<bool>(false);
  app.add_flag("--dump-mission", *mission, "print the default mission configuration (YAML)");
  app.add_option("--check", *check, "load a YAML config and report the first error");
  return [check, mission] {
    if (*mission) {
      fmt::print("{}", exploration::dump_mission_options(exploration::MissionOptions::defaults()));
      return 0;
    }
    if (!check->empty()) {
      predictor::load_pslam_options(*check);
      fmt::print("{}: ok\n", *check);
      return 0;
    }
    fmt::print("{}", predictor::dump_pslam_options({}));
    return 0;
  };
}

}  // namespace lookahead::app
