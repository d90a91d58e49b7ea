// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_keys.hpp"

#include <sstream>

namespace lookahead::exploration {

const std::vector<StudyKey>& study_keys() {
  static const std::vector<StudyKey> keys{
      {"name", "example", "required; letters, digits, '.', '_', '-'; names the output folder"},
      {"out", "out/study/example", "output folder (default out/study/<name>)"},
      {"worlds", "", "required, at least one world (keys below)"},
      {"strategies", "[nearest, utility]", "required; mission.strategy values"},
      {"seeds", "{from: 1, count: 2}", "required; a list [1, 2, 3] or {from, count}"},
      {"pose_source", "truth", "shortcut for mission.pose_source: slam | truth"},
      {"particles", "30", "shortcut for slam.filter.particles"},
      {"time_limit", "1800", "shortcut for mission.time_limit [s, simulated]"},
      {"coverage_goal", "0.95", "shortcut for mission.coverage_goal, (0, 1]"},
      {"mission", "{}", "overrides in the config/mission format (not strategy or seed)"},
  };
  return keys;
}

const std::vector<StudyKey>& study_world_keys() {
  static const std::vector<StudyKey> keys{
      {"name", "office",
       "required; office | maze | corridor, or a map .yaml, Stage .world or image file "
       "(relative to the study file's folder)"},
      {"resolution", "0.2", "image worlds: metres per pixel"},
      {"pixel_rule", "only_white", "image worlds: stage | only_white (which pixels are free)"},
      {"start", "[1.0, 2.0, 0.0]", "start pose [x, y, theta] in the world frame [m, m, rad]"},
      {"label", "office", "name in folders, tables and plots (default from the name)"},
      {"seed", "1", "generated worlds: the seed that fixes the floor"},
  };
  return keys;
}

std::set<std::string> key_names(const std::vector<StudyKey>& keys) {
  std::set<std::string> names;
  for (const StudyKey& k : keys) names.insert(k.key);
  return names;
}

std::string dump_study_keys() {
  std::ostringstream out;
  out << "# lookahead study file (lookahead config dump study): every key, with an example\n";
  for (const StudyKey& k : study_keys()) {
    if (std::string(k.key) != "worlds") {
      out << k.key << ": " << k.example << "  # " << k.doc << "\n";
      continue;
    }
    out << "worlds:  # " << k.doc << "\n";
    const char* lead = "  - ";
    for (const StudyKey& w : study_world_keys()) {
      out << lead << w.key << ": " << w.example << "  # " << w.doc << "\n";
      lead = "    ";
    }
  }
  return out.str();
}

}  // namespace lookahead::exploration
