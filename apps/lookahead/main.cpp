// SPDX-License-Identifier: MIT
// `lookahead`: exploration and mapping with structure prediction. See README.md.
#include <spdlog/cfg/env.h>
#include <spdlog/spdlog.h>

#include <cstdlib>
#include <exception>
#include <map>

#include "commands.hpp"
#include "lookahead/slam/io/parse_error.hpp"

int main(int argc, char** argv) {
  // Idle OpenMP workers sleep instead of spinning: on a 2-core machine shared with other
  // work a spinning worker steals the core the busy one needs. The user's setting wins.
  setenv("OMP_WAIT_POLICY", "passive", 0);
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows the mission's decisions
  CLI::App app{"lookahead: RBPF grid SLAM, exploration and structure prediction"};
  app.require_subcommand(1);
  std::map<CLI::App*, lookahead::app::Run> runs;
  auto add = [&](const char* name, const char* help, auto&& make) {
    CLI::App* sub = app.add_subcommand(name, help);
    runs[sub] = make(*sub);
  };
  add("explore", "explore a simulated building (default: the built-in office)", lookahead::app::add_explore_command);
  add("study", "run worlds x strategies x seeds of missions: tables, t-tests, plots",
      lookahead::app::add_study_command);
  add("hybrid-sim", "HybridSLAM simulations: Table 1, Fig. 3/4, NEES (Brooks & Bailey sec. 5)",
      lookahead::app::add_hybrid_sim_command);
  add("slam", "map a laser log (CARMEN, MRPT rawlog or ROS1 bag) with the RBPF", lookahead::app::add_slam_command);
  add("check", "report what a laser log or bag holds and what would mislead mapping",
      lookahead::app::add_check_command);
  add("slam3d", "3D mapping with the octree RBPF: simulated garage, geb079, or 3DTK scans",
      lookahead::app::add_slam3d_command);
  add("eval", "relative pose error of a trajectory; entropy of a map", lookahead::app::add_eval_command);
  add("predict", "one P-SLAM structure prediction on a saved map, with its picture",
      lookahead::app::add_predict_command);
  add("config", "print the documented default configuration", lookahead::app::add_config_command);
  CLI11_PARSE(app, argc, argv);
  try {
    for (auto& [sub, run] : runs) {
      if (sub->parsed()) return run();
    }
  } catch (const lookahead::slam::ParseError& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
  return 0;
}
