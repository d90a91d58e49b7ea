// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/slam_config.hpp"

#include <stdexcept>
#include <string>

#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"

namespace lookahead::slam {
namespace {

// The single list of keys: each section visits its fields with (key, field, doc). Loading
// and dumping both walk it, so the YAML names cannot drift from the structs.
template <typename V>
void visit_sections(RbpfOptions& o, V&& v) {
  v.section("filter");
  v("particles", o.particles, "number of particles N");
  v("seed", o.seed, "seed of every random draw");
  v("threads", o.threads, "worker threads, 0 = all cores");
  v("linear_update", o.linear_update, "update after this much travel [m]");
  v("angular_update", o.angular_update, "... or this much rotation [rad]");
  v("resample_threshold", o.resample_threshold, "resample when Neff < this * N");
  v("warmup_updates", o.warmup_updates, "updates that only insert scans");
  v("weight_exponent", o.weight_exponent, "k in w = w eta^k (flattens overconfident weights)");
  v.section("grid");
  v("resolution", o.grid.resolution, "cell side [m]");
  v("log_odds_hit", o.grid.log_odds_hit, "log-odds added where a beam ends");
  v("log_odds_miss", o.grid.log_odds_miss, "log-odds added where a beam passes");
  v("log_odds_min", o.grid.log_odds_min, "lower clamp");
  v("log_odds_max", o.grid.log_odds_max, "upper clamp");
  v("obstacle_on", o.grid.obstacle_on, "log-odds at which a cell becomes an obstacle");
  v("obstacle_off", o.grid.obstacle_off, "log-odds at which it stops being one");
  v("distance_field_radius", o.grid.distance_field_radius, "distance field kept up to [m]");
  v("max_usable_range", o.insert.max_usable_range, "beams inserted up to [m]");
  v("clear_no_returns", o.insert.clear_no_returns, "no-returns clear free space to max range");
  v("exact_rays", o.insert.exact_rays, "trace beams point to point, not cell centre to centre");
  v.section("motion");
  v("srr", o.motion.srr, "translation error per metre [m/m]");
  v("srt", o.motion.srt, "rotation error per metre [rad/m]");
  v("str", o.motion.str, "translation error per radian [m/rad]");
  v("stt", o.motion.stt, "rotation error per radian [rad/rad]");
  v("min_sigma_xy", o.motion.min_sigma_xy, "floor of the translation std [m]");
  v("min_sigma_theta", o.motion.min_sigma_theta, "floor of the rotation std [rad]");
  v.section("likelihood");
  v("sigma", o.likelihood.sigma, "end point std around a wall [m]");
  v("random_floor", o.likelihood.random_floor, "weight of unexplained readings");
  v("unknown_likelihood", o.likelihood.unknown_likelihood, "likelihood of an end point in unknown space");
  v("beam_step", o.likelihood.beam_step, "use every n-th beam");
  v("max_range", o.likelihood.max_range, "readings used up to [m]");
  v("temperature", o.likelihood.temperature, "exponent on the product over beams");
  v.section("matcher");
  v("linear_step", o.matcher.linear_step, "first step in x, y [m]");
  v("angular_step", o.matcher.angular_step, "first step in theta, at least the odometry's rotation std [rad]");
  v("refinements", o.matcher.refinements, "step halvings");
  v("max_iterations", o.matcher.max_iterations, "cap on accepted moves");
  v("min_hit_ratio", o.matcher.min_hit_ratio, "match fails below this share of end points on walls, [0, 1]");
  v("max_correction", o.matcher.max_correction, "match fails farther than this from odometry [m]");
  v.section("proposal");
  v("kind", o.proposal.kind,
    "scan_match (Grisetti 2007 improved proposal) | motion_model (odometry, weighted by the scan)");
  v("kernel_linear", o.proposal.kernel_linear, "spacing of the 27 kernel points in x, y [m]");
  v("kernel_angular", o.proposal.kernel_angular, "spacing in theta [rad]");
  v.section("prediction");
  v("enabled", o.prediction.enabled, "P-SLAM: hypotheses in the weights (--predict)");
  v("hit_ratio_threshold", o.prediction.hit_ratio_threshold, "hr_Th: prediction unused when every particle is below");
  v("min_predicted_beams", o.prediction.min_predicted_beams, "fewer end points on a hypothesis carry no evidence");
  v("max_hypotheses", o.prediction.max_hypotheses, "hypotheses kept at once (oldest dropped)");
}

}  // namespace

RbpfOptions parse_rbpf_options(const std::string& yaml, const std::string& source, const RbpfOptions& base,
                               const std::set<std::string>& other_sections) {
  return config::parse_options(
      yaml, source, base, [](RbpfOptions& o, auto& v) { visit_sections(o, v); },
      // The components validate their own options; no particles yet.
      [](const RbpfOptions& o) { const Rbpf check(o); }, other_sections);
}

RbpfOptions load_rbpf_options(const std::string& path, const RbpfOptions& base) {
  return parse_rbpf_options(config::read_text_file(path), path, base);
}

std::set<std::string> rbpf_section_names() {
  config::SectionNames names;
  RbpfOptions o;
  visit_sections(o, names);
  return names.names;
}

std::string dump_rbpf_options(const RbpfOptions& options) {
  return config::dump_options(options, [](RbpfOptions& o, auto& v) { visit_sections(o, v); });
}

}  // namespace lookahead::slam
