// SPDX-License-Identifier: MIT
#include "lookahead/slam/config/slam_config.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

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
  v("angular_step", o.matcher.angular_step, "first step in theta [rad]");
  v("refinements", o.matcher.refinements, "step halvings");
  v("max_iterations", o.matcher.max_iterations, "cap on accepted moves");
  v("min_hit_ratio", o.matcher.min_hit_ratio, "match fails below this share of end points on walls");
  v("max_correction", o.matcher.max_correction, "match fails farther than this from odometry [m]");
  v.section("proposal");
  v("kernel_linear", o.proposal.kernel_linear, "spacing of the 27 kernel points in x, y [m]");
  v("kernel_angular", o.proposal.kernel_angular, "spacing in theta [rad]");
  v("min_sigma_fraction", o.proposal.min_sigma_fraction, "floor of the fitted std, fraction of spacing");
}

class Loader {
 public:
  Loader(const YAML::Node& root, std::string source) : root_(root), source_(std::move(source)) {}
  void section(const char* name) {
    // reset(), not operator=: assigning to a yaml-cpp Node writes through to the node it
    // refers to (the previous section) instead of rebinding.
    current_.reset(root_[name]);
    name_ = name;
    if (current_ && !current_.IsMap()) fail(current_, name, "must be a map");
    if (current_) seen_sections_.insert(name);
  }
  template <typename T>
  void operator()(const char* key, T& field, const char*) {
    if (!current_) return;
    const YAML::Node n = current_[key];
    if (!n) return;
    seen_keys_.insert(name_ + "." + key);
    try {
      field = n.as<T>();
    } catch (const YAML::Exception&) {
      fail(n, name_ + "." + key, "bad value");
    }
  }
  void reject_unknown() const {
    for (const auto& s : root_) {
      const std::string sec = s.first.as<std::string>();
      if (!seen_sections_.count(sec)) fail(s.first, sec, "unknown section");
      for (const auto& k : s.second) {
        const std::string key = sec + "." + k.first.as<std::string>();
        if (!seen_keys_.count(key)) fail(k.first, key, "unknown key");
      }
    }
  }

 private:
  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const char* why) const {
    throw ParseError(source_, static_cast<std::size_t>(n.Mark().line + 1), key,
                     n.IsScalar() ? n.Scalar() : "", why);
  }
  YAML::Node root_, current_;
  std::string source_, name_;
  std::set<std::string> seen_sections_, seen_keys_;
};

class Dumper {
 public:
  void section(const char* name) { out_ << name << ":\n"; }
  template <typename T>
  void operator()(const char* key, const T& field, const char* doc) {
    // fmt prints the shortest text that reads back to the same value (0.05, not 0.0500...01).
    out_ << "  " << key << ": " << fmt::format("{}", field) << "  # " << doc << "\n";
  }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
};

}  // namespace

RbpfOptions parse_rbpf_options(const std::string& yaml, const std::string& source,
                               const RbpfOptions& base) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::ParserException& e) {
    throw ParseError(source, static_cast<std::size_t>(e.mark.line + 1), "", "", e.msg);
  }
  RbpfOptions o = base;
  if (root.IsNull()) return o;
  if (!root.IsMap()) throw ParseError(source, 1, "", "", "top level must be a map of sections");
  Loader loader(root, source);
  visit_sections(o, loader);
  loader.reject_unknown();
  try {
    const Rbpf check(o);  // the components validate their own options; no particles yet
  } catch (const std::invalid_argument& e) {
    throw ParseError(source, 0, "", "", std::string("impossible value: ") + e.what());
  }
  return o;
}

RbpfOptions load_rbpf_options(const std::string& path, const RbpfOptions& base) {
  std::ifstream in(path);
  if (!in) throw ParseError(path, 0, "", "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_rbpf_options(text.str(), path, base);
}

std::string dump_rbpf_options(const RbpfOptions& options) {
  RbpfOptions copy = options;
  Dumper d;
  visit_sections(copy, d);
  return d.str();
}

}  // namespace lookahead::slam
