// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_config.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "lookahead/exploration/mission_config.hpp"
#include "lookahead/exploration/study_keys.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::exploration {
namespace {

namespace fs = std::filesystem;

// The node at a dotted path below `map` ("slam.filter.particles"), or an undefined node.
YAML::Node at_path(const YAML::Node& map, const std::string& path) {
  if (!map.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const std::size_t dot = path.find('.');
  const YAML::Node child = map[path.substr(0, dot)];
  if (!child || dot == std::string::npos) return child;
  return at_path(child, path.substr(dot + 1));
}

class StudyParser {
 public:
  StudyParser(std::string yaml, std::string source, std::string base_dir)
      : yaml_(std::move(yaml)), source_(std::move(source)), base_dir_(std::move(base_dir)) {}

  StudySpec parse(const YAML::Node& root) {
    StudySpec s;
    s.source = source_;
    check_keys(root, "", key_names(study_keys()));
    s.name = get<std::string>(required(root, "name", root), "name");
    if (!is_label(s.name)) fail(root["name"], "name", "use letters, digits, '.', '_' and '-' only");
    s.out = root["out"] ? get<std::string>(root["out"], "out") : "out/study/" + s.name;
    s.worlds = worlds(required(root, "worlds", root));
    s.strategies = strategies(required(root, "strategies", root));
    s.seeds = seeds(required(root, "seeds", root));
    if (s.worlds.size() * s.strategies.size() * s.seeds.size() > slam::limits::kMaxStudyRuns) {
      fail(root["seeds"], "seeds",
           std::to_string(s.worlds.size() * s.strategies.size() * s.seeds.size()) +
               " runs (worlds x strategies x seeds), over the limit of 100000 (limits::kMaxStudyRuns)");
    }
    s.mission = mission(root);
    for (const std::string& strategy : s.strategies) {
      MissionOptions o = s.mission;
      o.strategy = strategy;
      validate(o, root["strategies"]);
    }
    return s;
  }

 private:
  template <typename T>
  T get(const YAML::Node& n, const std::string& key) const {
    try {
      return n.as<T>();
    } catch (const YAML::Exception&) {
      fail(n, key, "bad value");
    }
  }
  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& why) const {
    throw slam::ParseError(source_, static_cast<std::size_t>(n.Mark().line + 1), key, n.IsScalar() ? n.Scalar() : "",
                           why);
  }
  YAML::Node required(const YAML::Node& map, const char* key, const YAML::Node& where) const {
    const YAML::Node n = map[key];
    if (!n) fail(where, key, "missing");
    return n;
  }
  void check_keys(const YAML::Node& map, const std::string& prefix, const std::set<std::string>& known) const {
    if (!map.IsMap()) fail(map, prefix.empty() ? "study" : prefix, "must be a map");
    for (const auto& kv : map) {
      const std::string key = kv.first.as<std::string>();
      if (!known.count(key)) fail(kv.first, prefix + key, "unknown key");
    }
  }
  static bool is_label(const std::string& s) {
    if (s.empty()) return false;
    for (const char c : s) {
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') return false;
    }
    return true;
  }

  std::vector<StudyWorld> worlds(const YAML::Node& list) const {
    if (!list.IsSequence() || list.size() == 0) fail(list, "worlds", "must be a non-empty list");
    std::vector<StudyWorld> out;
    std::set<std::string> labels;
    for (const YAML::Node& w : list) {
      out.push_back(world(w));
      if (!labels.insert(out.back().label).second)
        fail(w, "worlds.label", "two worlds share the label " + out.back().label);
    }
    return out;
  }

  // A plain image, which (unlike a map_server .yaml or a Stage .world) carries no scale.
  static bool is_image(const std::string& name) {
    const std::string ext = fs::path(name).extension().string();
    return ext != ".yaml" && ext != ".yml" && ext != ".world" && name != "office" && name != "maze" &&
           name != "corridor";
  }

  StudyWorld world(const YAML::Node& w) const {
    check_keys(w, "worlds.", key_names(study_world_keys()));
    StudyWorld sw;
    sw.line = static_cast<std::size_t>(w.Mark().line + 1);
    const std::string name = get<std::string>(required(w, "name", w), "worlds.name");
    const bool generated = name == "office" || name == "maze" || name == "corridor";
    sw.spec.name = generated ? name : (fs::path(base_dir_) / name).lexically_normal().string();
    sw.label =
        generated ? name : fs::path(name).filename().string().substr(0, fs::path(name).filename().string().find('.'));
    if (w["label"]) sw.label = get<std::string>(w["label"], "worlds.label");
    if (!is_label(sw.label))
      fail(w["label"] ? w["label"] : w, "worlds.label", "use letters, digits, '.', '_' and '-' only");
    if (w["resolution"]) {
      sw.spec.image_resolution = get<double>(w["resolution"], "worlds.resolution");
      if (!(sw.spec.image_resolution > 0)) fail(w["resolution"], "worlds.resolution", "must be > 0");
    } else if (is_image(name)) {
      fail(w, "worlds.resolution", "missing: an image world (" + name + ") needs its m/pixel stated");
    }
    if (const YAML::Node r = w["pixel_rule"]) {
      sw.spec.pixel_rule = get<std::string>(r, "worlds.pixel_rule");
      if (sw.spec.pixel_rule != "stage" && sw.spec.pixel_rule != "only_white") {
        fail(r, "worlds.pixel_rule", "bad value: expected stage | only_white");
      }
    }
    if (w["seed"]) sw.spec.seed = get<std::uint64_t>(w["seed"], "worlds.seed");
    if (const YAML::Node st = w["start"]) {
      const auto v = get<std::vector<double>>(st, "worlds.start");
      if (v.size() != 3) fail(st, "worlds.start", "must be [x, y, theta]");
      sw.spec.start = slam::Pose2{v[0], v[1], v[2]};
    }
    return sw;
  }

  std::vector<std::string> strategies(const YAML::Node& list) const {
    if (!list.IsSequence() || list.size() == 0) fail(list, "strategies", "must be a non-empty list");
    std::vector<std::string> out;
    for (const YAML::Node& s : list) {
      out.push_back(get<std::string>(s, "strategies"));
      if (std::count(out.begin(), out.end(), out.back()) > 1) fail(s, "strategies", "listed twice");
    }
    return out;
  }

  std::vector<std::uint64_t> seeds(const YAML::Node& n) const {
    std::vector<std::uint64_t> out;
    if (n.IsMap()) {
      check_keys(n, "seeds.", {"from", "count"});
      const auto from = get<std::uint64_t>(required(n, "from", n), "seeds.from");
      const auto count = get<int>(required(n, "count", n), "seeds.count");
      if (count < 1) fail(n["count"], "seeds.count", "must be >= 1");
      if (static_cast<std::size_t>(count) > slam::limits::kMaxStudyRuns) {
        fail(n["count"], "seeds.count", "over the limit of 100000 runs per study (limits::kMaxStudyRuns)");
      }
      for (int i = 0; i < count; ++i) out.push_back(from + static_cast<std::uint64_t>(i));
    } else if (n.IsSequence() && n.size() > 0) {
      if (n.size() > slam::limits::kMaxStudyRuns) {
        fail(n, "seeds", "over the limit of 100000 runs per study (limits::kMaxStudyRuns)");
      }
      for (const YAML::Node& s : n) {
        out.push_back(get<std::uint64_t>(s, "seeds"));
        if (std::count(out.begin(), out.end(), out.back()) > 1) fail(s, "seeds", "listed twice");
      }
    } else {
      fail(n, "seeds", "must be a non-empty list or {from, count}");
    }
    return out;
  }

  MissionOptions mission(const YAML::Node& root) const;
  void validate(MissionOptions& o, const YAML::Node& where) const {
    o.harmonize();
    try {
      o.validate();
    } catch (const std::invalid_argument& e) {
      fail(where, "", std::string("impossible value: ") + e.what());
    }
  }

  std::string yaml_, source_, base_dir_;
};

// Shortcuts first, then the mission block on top; a key set in both places is an error, so
// neither silently wins. The block must leave strategy and seed to the study.
MissionOptions StudyParser::mission(const YAML::Node& root) const {
  MissionOptions o = MissionOptions::defaults();
  if (const YAML::Node n = root["pose_source"]) {
    const auto p = pose_source_from_name(get<std::string>(n, "pose_source"));
    if (!p) fail(n, "pose_source", "bad value: expected slam | truth");
    o.pose_source = *p;
  }
  if (root["particles"]) o.slam.particles = get<int>(root["particles"], "particles");
  if (root["time_limit"]) o.time_limit = get<double>(root["time_limit"], "time_limit");
  if (root["coverage_goal"]) o.coverage_goal = get<double>(root["coverage_goal"], "coverage_goal");
  validate(o, root);
  const YAML::Node block = root["mission"];
  if (!block) return o;
  if (!block.IsMap()) fail(block, "mission", "must be a map");
  const std::pair<const char*, const char*> owned[] = {
      {"mission.strategy", "strategies"},         {"mission.seed", "seeds"},
      {"mission.pose_source", "pose_source"},     {"mission.time_limit", "time_limit"},
      {"mission.coverage_goal", "coverage_goal"}, {"slam.filter.particles", "particles"}};
  for (const auto& [inner, outer] : owned) {
    const YAML::Node n = at_path(block, inner);
    const bool always_owned = std::string(outer) == "strategies" || std::string(outer) == "seeds";
    if (n && (always_owned || root[outer]))
      fail(n, std::string("mission.") + inner, std::string("set by the study's ") + outer);
  }
  const std::string text = block.Style() == YAML::EmitterStyle::Flow
                               ? std::string(static_cast<std::size_t>(block.Mark().line), '\n') + YAML::Dump(block)
                               : yaml_block_text(yaml_, block.Mark().line, block.Mark().column);
  return parse_mission_options(text, source_, o);
}

}  // namespace

StudySpec parse_study(const std::string& yaml, const std::string& source, const std::string& base_dir) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::ParserException& e) {
    throw slam::ParseError(source, static_cast<std::size_t>(e.mark.line + 1), "", "", e.msg);
  }
  if (!root.IsMap())
    throw slam::ParseError(source, 1, "", "", "a study file is a map (name, worlds, strategies, seeds...)");
  return StudyParser(yaml, source, base_dir).parse(root);
}

StudySpec load_study(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw slam::ParseError(path, 0, "", "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  const std::string dir = fs::path(path).parent_path().string();
  return parse_study(text.str(), path, dir.empty() ? "." : dir);
}

}  // namespace lookahead::exploration
