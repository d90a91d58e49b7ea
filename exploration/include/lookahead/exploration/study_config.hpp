// SPDX-License-Identifier: MIT
// A study file: which worlds, strategies and seeds to cross, and the mission options they
// share. Keys:
//   name: kth_quick                  # required; names the default output folder
//   out: out/study/kth_quick         # default out/study/<name>, relative to the working dir
//   worlds:                          # required, at least one
//     - {name: office}               # office | maze | a map .yaml, Stage .world or image
//     - {name: plans/a.png, resolution: 0.2, pixel_rule: only_white, start: [x, y, theta],
//        label: a, seed: 1}          # resolution and pixel_rule (stage | only_white): images
//   strategies: [nearest, utility]   # required
//   seeds: [1, 2, 3]                 # or {from: 1, count: 10}
//   pose_source: truth               # shortcuts for mission.pose_source, slam.filter.particles,
//   particles: 30                    #   mission.time_limit, mission.coverage_goal
//   time_limit: 1800
//   coverage_goal: 0.99
//   mission: {...}                   # overrides in the config/mission format
// A world file path is relative to the study file's folder. Errors are slam::ParseError with
// the file, line, key and value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lookahead/exploration/mission_options.hpp"
#include "lookahead/exploration/world_source.hpp"

namespace lookahead::exploration {

struct StudyWorld {
  /// What load_world() gets; a file name already resolved against the study's folder. The
  /// spec's seed (default 1) fixes a generated world, so every run of a study explores the
  /// same floor.
  WorldSpec spec;
  /// Name in folders, tables and plots: letters, digits, '.', '_' and '-'; default "office",
  /// "maze" or the file name up to its first '.'.
  std::string label;
  std::size_t line = 0;  ///< where the study file names it, for messages
};

struct StudySpec {
  std::string name;
  std::string out;  ///< output folder
  std::vector<StudyWorld> worlds;
  std::vector<std::string> strategies;
  std::vector<std::uint64_t> seeds;
  /// Shared by every run: defaults, then the shortcuts, then the `mission:` block; each run
  /// sets its own strategy and seed (so the block must not).
  MissionOptions mission = MissionOptions::defaults();
  std::string source;  ///< the study file, for messages
};

StudySpec load_study(const std::string& path);
/// `source` names the text in errors; `base_dir` is where relative world paths start.
StudySpec parse_study(const std::string& yaml, const std::string& source, const std::string& base_dir);

}  // namespace lookahead::exploration
