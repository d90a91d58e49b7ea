// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission_config.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <sstream>
#include <stdexcept>

#include "lookahead/predictor/predictor_keys.hpp"
#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"

namespace lookahead::exploration {
namespace {

// The single list of keys: each section visits its fields with (key, field, doc). Loading
// and dumping both walk it, so the YAML names cannot drift from the structs. Two halves:
// the mission and the simulated robot, then the planning components.
template <typename V>
void visit_robot_sections(MissionOptions& o, V&& v) {
  v.section("mission");
  v("strategy", o.strategy,
    "target selection: nearest | utility | advantage | rate | predictive | predictive-utility | "
    "predictive-advantage | predictive-rate");
  v("utility_lambda", o.utility_lambda, "utility = gain [m^2] - lambda * cost [m]");
  v("rate_offset", o.rate_offset, "rate = gain [m^2] / (2 cost - nearest cost + offset) [m], > 0");
  v("pose_source", o.pose_source, "slam (RBPF in the loop) | truth (map at the true pose)");
  v("seed", o.seed, "seeds the sensor, odometry, SLAM (filter.seed) and planner");
  v("time_limit", o.time_limit, "simulated seconds, > 0");
  v("coverage_goal", o.coverage_goal, "stop at this share of the reachable free area, (0, 1]");
  v("goal_check_period", o.goal_check_period, "the current goal is re-examined this often [s]");
  v("stuck_time", o.stuck_time, "no progress this long blacklists the goal [s]");
  v("detour_progress", o.detour_progress,
    "on a detour (path > 10 m and > 2x the distance) a shorter path left is progress");
  v("max_goal_attempts", o.max_goal_attempts, "candidates tried per selection before trapped");
  v("metrics_period", o.metrics_period, "coverage is sampled this often [s]");
  v("frame_period", o.frame_period, "animation frame every [s]; 0 = no animation");
  v("initial_turn", o.initial_turn, "turn in place at the start [rad]");
  v("free_threshold", o.free_threshold, "a map cell below this occupancy is free (frontiers), (0, 0.5)");
  v("recovery_order", o.recovery_order,
    "recovery behaviours tried in this order when no frontier can be planned to: comma-separated, each at most "
    "once, of backtrack | last_resort | second_chance | look_around");
  v("safety_margin", o.safety_margin, "planning clearance beyond the robot radius [m]");
  v("stop_distance", o.stop_distance, "reactive stop for laser points this close ahead [m]");
  v.section("robot");
  v("radius", o.robot.radius, "disc radius [m], > 0");
  v("max_speed", o.robot.max_speed, "[m/s], > 0");
  v("max_turn_rate", o.robot.max_turn_rate, "[rad/s], > 0");
  v.section("laser");
  v("fov", o.laser.fov, "field of view [rad], (0, 2 pi]");
  v("angular_resolution", o.laser.angular_resolution, "beam spacing [rad], > 0");
  v("max_range", o.laser.max_range, "[m], > 0; also the SLAM likelihood's max_range");
  v("range_sigma", o.laser.range_sigma, "Gaussian range noise [m], >= 0");
  v("rate_hz", o.laser.rate_hz, "scans per second, > 0 (the simulator's clock)");
  v.section("odometry");
  v("srr", o.odometry.srr, "simulated drift: translation per metre [m/m]");
  v("srt", o.odometry.srt, "rotation per metre [rad/m]");
  v("str", o.odometry.str, "translation per radian [m/rad]");
  v("stt", o.odometry.stt, "rotation per radian [rad/rad]");
}

// P-SLAM look-ahead mapping: the predictor's options and their use in exploration. (The
// filter's use of hypotheses is slam.prediction.)
template <typename V>
void visit_lookahead_section(LookaheadOptions& o, V&& v) {
  v.section("lookahead");
  v("enabled", o.enabled, "predict at each new target (on with --predict or strategy predictive)");
  v("latency", o.latency, "a prediction is delivered this long after its request [s, simulated]");
  v("skip", o.skip,
    "predictive strategies skip a frontier when: region (its region is predicted) | far_side (its "
    "far side is)");
  v("skip_confidence", o.skip_confidence, "... counting hypotheses with Psi >= this");
  v("skip_share", o.skip_share, "far_side: ... this share of its far side is predicted");
  v("skip_region_radius", o.skip_region_radius, "region: ... its region within this is predicted [m], > 0");
  v("skip_region_wall_gap", o.skip_region_wall_gap,
    "... a wall's unknown gaps up to this wide (and the robot's diameter) close the region [m]");
  v("known_boundary", o.known_boundary, "... and no region reaches beyond the world's extent (Fig. 7(d))");
  v("skip_wall_slivers", o.skip_wall_slivers,
    "... and skip frontiers whose region is a closed pocket of min_predicted_area");
  v("targets_per_selection", o.targets_per_selection,
    "frontiers predicted per selection: the target, then the nearest");
  v("predict_while_idle", o.predict_while_idle, "an idle predictor predicts the nearest frontiers not covered yet");
  v("repredict_after", o.repredict_after, "... a frontier again after this long [s, simulated]");
  v("repredict_growth", o.repredict_growth,
    "... and once the known cells of its surroundings grew by this share (0: at once), >= 0");
  v("pictures", o.pictures, "write predictions/NNN.png and .pgm per hypothesis into the run folder (diagnosis)");
  predictor::visit_predictor_keys(o.predictor, v);
}

template <typename V>
void visit_planning_sections(MissionOptions& o, V&& v) {
  v.section("planner");
  v("algorithm", o.planner.algorithm, "rrt_star | prm_star | informed_rrt_star");
  v("time_budget", o.planner.time_budget, "wall-clock budget of a search without a sample budget [s], (0, 60]");
  v("max_samples", o.planner.max_samples, "samples per search, 0 = no limit");
  v("samples_per_m2", o.planner.samples_per_m2,
    "samples per m^2 of the ellipse the Dijkstra price bounds (>= 300, <= max_samples); 0 = off");
  v("goal_tolerance", o.planner.goal_tolerance, "a path may end this close to the goal [m]");
  v("simplify", o.planner.simplify, "shortcut and smooth the found path");
  v("unknown_is_free", o.planner.costmap.unknown_is_free, "plan through never-observed cells");
  v("occupied_threshold", o.planner.costmap.occupied_threshold, "occupancy that blocks a cell, (0.5, 1]");
  v.section("follower");
  v("lookahead", o.follower.lookahead, "pure-pursuit look-ahead arc length [m]");
  v("rotate_in_place_angle", o.follower.rotate_in_place_angle, "heading error that stops forward motion [rad]");
  v("goal_tolerance", o.follower.goal_tolerance, "goal reached within [m]");
  v.section("frontiers");
  v("min_cluster_cells", o.frontiers.min_cluster_cells, "smaller frontier clusters are noise");
  v("cluster_gap", o.frontiers.cluster_gap, "frontier cells this many cells apart join one cluster");
  v("goal_search_radius", o.frontiers.goal_search_radius, "a goal may move this far from its cluster [m]");
  v.section("blacklist");
  v("radius", o.blacklist.radius, "goals this close to a failed one are skipped [m]");
  v("lifetime", o.blacklist.lifetime, "mission seconds an entry lasts");
  v("max_strikes", o.blacklist.max_strikes, "the n-th entry at one spot lasts for good, >= 1");
  visit_lookahead_section(o.lookahead, v);
}

template <typename V>
void visit_sections(MissionOptions& o, V&& v) {
  visit_robot_sections(o, v);
  visit_planning_sections(o, v);
}

using slam::config::fail_at;

// The slam section goes to the SLAM library's loader as text of its own, padded so that its
// errors carry this file's line numbers.
slam::RbpfOptions parse_slam_section(const std::string& text, const YAML::Node& node, const std::string& source,
                                     const slam::RbpfOptions& base) {
  if (!node.IsMap()) fail_at(source, node, "slam", "must be a map");
  const int line = node.Mark().line, column = node.Mark().column;
  if (node.size() == 0) return base;
  if (node.Style() != YAML::EmitterStyle::Flow) {
    return slam::parse_rbpf_options(yaml_block_text(text, line, column), source, base);
  }
  YAML::Emitter flow;  // a flow map may span lines; re-emitted on one, errors name its first
  flow << YAML::Flow << node;
  return slam::parse_rbpf_options(std::string(static_cast<std::size_t>(line), '\n') + flow.c_str(), source, base);
}

}  // namespace

const char* pose_source_name(PoseSource source) { return slam::config::choice_name(source); }

std::optional<PoseSource> pose_source_from_name(const std::string& name) {
  return slam::config::choice_from_name<PoseSource>(name);
}

std::string yaml_block_text(const std::string& text, int line, int column) {
  std::istringstream in(text);
  std::string out(static_cast<std::size_t>(std::max(line, 0)), '\n'), l;
  const auto col = static_cast<std::size_t>(std::max(column, 0));
  for (int i = 0; std::getline(in, l); ++i) {
    if (i < line) continue;
    const std::size_t first = l.find_first_not_of(' ');
    const bool blank = first == std::string::npos || l[first] == '#';
    if (i == line) {
      out += l.substr(std::min(col, l.size())) + "\n";  // may follow "key:" on the same line
    } else if (blank) {
      out += "\n";
    } else if (first < col) {
      break;
    } else {
      out += l.substr(col) + "\n";
    }
  }
  return out;
}

MissionOptions parse_mission_options(const std::string& yaml, const std::string& source, const MissionOptions& base) {
  const YAML::Node root = slam::config::parse_sections(yaml, source);
  MissionOptions o = base;
  if (root.IsNull()) return o;
  slam::config::SectionLoader loader(root, source);
  visit_sections(o, loader);
  loader.reject_unknown({"slam"});  // read by the SLAM library's own loader below
  if (const YAML::Node s = root["slam"]) o.slam = parse_slam_section(yaml, s, source, o.slam);
  o.harmonize();
  try {
    o.validate();
  } catch (const std::invalid_argument& e) {
    loader.fail_impossible(e.what());
  }
  return o;
}

MissionOptions load_mission_options(const std::string& path, const MissionOptions& base) {
  return parse_mission_options(slam::config::read_text_file(path), path, base);
}

std::string dump_mission_options(const MissionOptions& options) {
  const std::string own = slam::config::dump_options(options, [](MissionOptions& o, auto& v) { visit_sections(o, v); });
  std::string slam_text = slam::dump_rbpf_options(options.slam), indented;
  std::istringstream in(slam_text);
  for (std::string l; std::getline(in, l);) indented += "  " + l + "\n";
  return "# lookahead mission defaults (lookahead config dump mission): every key, with its unit\n" + own +
         "# RBPF options in the config/slam format. Derived, whatever is written here:\n"
         "# filter.seed from mission.seed, likelihood.max_range from laser.max_range.\n"
         "slam:\n" +
         indented;
}

}  // namespace lookahead::exploration
