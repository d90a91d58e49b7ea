// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/hybrid_config.hpp"

#include <fmt/ranges.h>

#include <stdexcept>

#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/hybrid/feature_existence.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam::hybrid {
namespace {

template <typename V>
void visit_sections(HybridConfig& c, V&& v) {
  HybridOptions& f = c.filter;
  v.section("sensor");
  v("max_range", f.sensor.max_range, "range of the range-bearing sensor [m]");
  v("sigma_range", f.sensor.sigma_range, "range noise std [m]");
  v("sigma_bearing", f.sensor.sigma_bearing, "bearing noise std [rad]");
  v.section("existence");
  v("alpha", f.existence.alpha, "p(detection | feature in view) (study levels override)");
  v("beta", f.existence.beta, "p(false alarm | feature in view) (study levels override)");
  v("prior", f.existence.prior, "existence before the creating observation");
  v("fuse_threshold", f.existence.fuse_threshold, "only features above are fused");
  v("cull_threshold", f.existence.cull_threshold, "features below are deleted");
  v("view_margin", f.existence.view_margin, "missed detections count this far inside the range [m]");
  v("clamp", f.existence.clamp, "alpha, beta clamped into [clamp, 1 - clamp]");
  v.section("process_floor");
  v("xy", f.process_floor.xy, "least position noise per step [m/sqrt(s)]");
  v("theta", f.process_floor.theta, "least heading noise per step [rad/sqrt(s)]");
  v.section("fastslam");
  v("particles", f.fastslam.particles, "particles P");
  v("resample_threshold", f.fastslam.resample_threshold, "resample when N_eff < this * P");
  v("new_feature_likelihood", f.fastslam.new_feature_likelihood, "likelihood of a new feature [1/(m rad)]");
  v("candidate_radius", f.fastslam.candidate_radius, "features considered within [m]");
  v("gate_chi2", f.fastslam.gate_chi2, "individual association gate (2 dof)");
  v("seed", f.fastslam.seed, "seed of the filter's draws (single runs)");
  v.section("fusion");
  v("period", f.fusion.period, "local map age at fusion [s]");
  v("jcbb_confidence", f.fusion.jcbb_confidence, "joint compatibility test level");
  v("jcbb_max_nodes", f.fusion.jcbb_max_nodes, "cap on the JCBB search");
  v("association_sigma", f.fusion.association_sigma, "std added to pair differences in the association test [m]");
  v("relinearise", f.fusion.relinearise, "re-solve all local maps by Gauss-Newton at each fusion");
  v("relinearise_iterations", f.fusion.relinearise_iterations, "Gauss-Newton steps per fusion, at most");
  SimulationOptions& s = c.simulation;
  v.section("simulation");
  v("world_size", s.world_size, "side of the square world [m]");
  v("features", s.features, "point features per world");
  v("speed", s.speed, "linear velocity [m/s]");
  v("max_turn_rate", s.max_turn_rate, "[rad/s]");
  v("steering_gain", s.steering_gain, "turn rate per radian of heading error [1/s]");
  v("dt", s.dt, "control and observation period [s]");
  v("inset", s.inset, "loop distance from the border [m]");
  v("inset_jitter", s.inset_jitter, "random inward shift of waypoints [m]");
  v("loop_overlap", s.loop_overlap, "travel past the start [m]");
  v("velocity_noise", s.velocity_noise, "std of v as a fraction of v");
  v("turn_noise", s.turn_noise, "std of omega as a fraction of omega");
  v("compass", s.compass, "heading known exactly (Fig. 3)");
  StudyOptions& t = c.study;
  v.section("study");
  v("alphas", t.alphas, "clutter levels: p(detection)");
  v("betas", t.betas, "clutter levels: p(false alarm)");
  v("trials", t.trials, "trials per filter and level");
  v("worlds", t.worlds, "distinct worlds");
  v("seed", t.seed, "seed of worlds, noise and filters");
  v("threads", t.threads, "0 = all cores");
  v("failure_sigma", t.failure_sigma, "failure: truth beyond this many std ...");
  v("failure_iterations", t.failure_iterations, "... for more than this many iterations");
  ScanLandmarkOptions& l = c.scan_landmarks;
  v.section("scan_landmarks");
  v("max_range", l.max_range, "beams used up to; on logs also the filter's sensor range [m]");
  v("break_distance", l.break_distance, "a run of beams breaks where neighbours are farther apart [m] (+ 3 r dphi)");
  v("split_tolerance", l.split_tolerance, "split a run where a point is this far from the chord [m]");
  v("min_points", l.min_points, "beams per segment");
  v("min_length", l.min_length, "segment length [m]");
  v("corner_min_angle", l.corner_min_angle, "two segments meet at least this sharply for a corner [rad]");
  v("corner_max_gap", l.corner_max_gap, "the corner lies this close to the shared beam [m]");
  v("occlusion_margin", l.occlusion_margin,
    "a line end is free when the next beam is this much farther or missing [m]");
  v("continuation_distance", l.continuation_distance, "... unless that beam lies this close to the segment's line [m]");
  v("min_incidence", l.min_incidence, "a line end's beam meets its line at least this steeply [rad]");
  v("line_ends", l.line_ends, "report free line ends (else corners only)");
  v("corner_sigma", l.corner_sigma, "corner position std [m]");
  v("end_sigma_across", l.end_sigma_across, "line end std across its line [m]");
  v("end_sigma_along", l.end_sigma_along, "line end std along its line, plus the beam gap [m]");
}

}  // namespace

HybridConfig parse_hybrid_config(const std::string& yaml, const std::string& source, const HybridConfig& base) {
  return slam::config::parse_options(
      yaml, source, base, [](HybridConfig& c, auto& v) { visit_sections(c, v); },
      [](const HybridConfig& c) {
        const FeatureExistence check(c.filter.existence);
        if (c.filter.fastslam.particles < 1) throw std::invalid_argument("fastslam.particles must be >= 1");
        if (!(c.filter.fusion.period > 0.0)) throw std::invalid_argument("fusion.period must be > 0");
        if (c.filter.fusion.relinearise_iterations < 1)
          throw std::invalid_argument("fusion.relinearise_iterations must be >= 1");
        if (c.study.alphas.size() != c.study.betas.size())
          throw std::invalid_argument("study.alphas and study.betas differ in length");
        if (!(c.simulation.dt > 0.0)) throw std::invalid_argument("simulation.dt must be > 0");
        validate(c.scan_landmarks);
      });
}

HybridConfig load_hybrid_config(const std::string& path, const HybridConfig& base) {
  return parse_hybrid_config(slam::config::read_text_file(path), path, base);
}

// On logs only the filter and scan_landmarks sections apply, on top of the log-mode
// defaults (100 particles, alpha 0.5, beta 0.1, ...). A file with the simulation's sections
// is a simulation file (config/hybrid/default.yaml lists every key): its filter values
// would silently replace the log-mode ones, so it is refused, naming the section's line.
HybridConfig load_hybrid_log_config(const std::string& path, const HybridConfig& base) {
  const std::string text = slam::config::read_text_file(path);
  const YAML::Node root = slam::config::parse_sections(text, path);
  if (root.IsMap()) {
    for (const auto& section : root) {
      const std::string name = section.first.as<std::string>();
      if (name != "simulation" && name != "study") continue;
      throw ParseError(path, section.first.Mark().line + 1, name, "",
                       "a hybrid-sim section in a log config: its file's filter values would replace the "
                       "log-mode defaults; give only the keys to change (e.g. config/hybrid/csail.yaml)");
    }
  }
  return parse_hybrid_config(text, path, base);
}

std::string dump_hybrid_config(const HybridConfig& config) {
  return slam::config::dump_options(config, [](HybridConfig& c, auto& v) { visit_sections(c, v); });
}

}  // namespace lookahead::slam::hybrid
