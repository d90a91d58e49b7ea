// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf3d/slam3d_config.hpp"

#include <stdexcept>

#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

// The single list of keys, walked by both the loader and the dumper.
template <typename V>
void visit_sections(Slam3dOptions& o, V&& v) {
  Rbpf3dOptions& f = o.filter;
  v.section("filter");
  v("particles", f.particles, "number of particles N");
  v("seed", f.seed, "seed of every random draw of the filter (--data-seed: the simulator)");
  v("threads", f.threads, "worker threads, 0 = all cores");
  v("resample_threshold", f.resample_threshold, "resample when Neff < this * N");
  v("weight_exponent", f.weight_exponent, "k in w = w p(z|x,m)^k (flattens overconfident weights)");
  v("likelihood_ray_step", f.likelihood_ray_step, "score every n-th beam that hit");
  v("insert_ray_step", f.insert_ray_step, "insert every n-th beam");
  v.section("map");
  v("resolution", f.map.resolution, "voxel side [m]");
  v("log_odds_hit", f.map.log_odds_hit, "added where a beam ends (OctoMap: p 0.7)");
  v("log_odds_miss", f.map.log_odds_miss, "added where a beam passes (OctoMap: p 0.4)");
  v("log_odds_min", f.map.log_odds_min, "lower clamp (OctoMap: p 0.1192)");
  v("log_odds_max", f.map.log_odds_max, "upper clamp (OctoMap: p 0.971)");
  v("occupied_above", f.map.occupied_above, "log-odds above which a voxel is occupied");
  v("max_insert_range", f.insert.max_range, "beams inserted up to [m]");
  v.section("likelihood");
  v("sigma", f.likelihood.sigma, "end point std around a surface [m]");
  v("random_floor", f.likelihood.random_floor, "likelihood of an unexplained end point");
  v("unknown_likelihood", f.likelihood.unknown_likelihood, "likelihood of an end point in unknown space");
  v.section("motion");
  v("xy_per_metre", f.motion.xy_per_metre, "x, y std per metre travelled [m/m]");
  v("z_per_metre", f.motion.z_per_metre, "z std per metre [m/m]");
  v("yaw_per_metre", f.motion.yaw_per_metre, "yaw std per metre [rad/m]");
  v("yaw_per_radian", f.motion.yaw_per_radian, "yaw std per radian turned [rad/rad]");
  v("min_xy", f.motion.min_xy, "floor of the x, y std per update [m]");
  v("min_yaw", f.motion.min_yaw, "floor of the yaw std per update [rad]");
  CaveCrawlerOptions& r = o.robot;
  v.section("robot");
  v("speed", r.speed, "driving speed [m/s]");
  v("turn_rate", r.turn_rate, "turning on the spot [rad/s]");
  v("world_resolution", o.world_resolution, "voxel side of the generated garage [m]");
  v("lines_per_sweep", r.laser.lines_per_sweep, "2D scans per half turn of the spinning laser");
  v("beams_per_line", r.laser.beams_per_line, "beams across the 180 deg fan");
  v("sweep_period", r.laser.sweep_period, "half-turn time [s]");
  v("max_range", r.laser.max_range, "laser range [m]");
  v("range_sigma", r.laser.range_sigma, "range noise std [m]");
  v("mount_height", r.laser.mount_height, "laser above the base [m]");
  v("speed_scale_sigma", r.dead_reckoning.speed_scale_sigma, "odometry scale error std (once per run)");
  v("speed_noise", r.dead_reckoning.speed_noise, "speed noise [m/s]");
  v("yaw_bias", r.dead_reckoning.yaw_bias, "gyro yaw bias [rad/s]");
  v("yaw_rate_noise", r.dead_reckoning.yaw_rate_noise, "yaw-rate noise [rad/s]");
  v("tilt_sigma", r.dead_reckoning.tilt_sigma, "IMU roll/pitch noise [rad]");
  v.section("threedtk");
  v("no_return_range", o.threedtk.no_return_range, "points at or beyond are no-returns [m]");
  v("point_step", o.threedtk.point_step, "keep every n-th point");
}

}  // namespace

Slam3dOptions parse_slam3d_options(const std::string& yaml, const std::string& source, const Slam3dOptions& base) {
  return config::parse_options(
      yaml, source, base, [](Slam3dOptions& o, auto& v) { visit_sections(o, v); },
      [](const Slam3dOptions& o) {
        o.filter.validate();
        o.robot.validate();
        if (o.threedtk.point_step < 1) throw std::invalid_argument("threedtk: point_step must be >= 1");
        if (!(o.world_resolution > 0.0)) throw std::invalid_argument("robot: world_resolution must be > 0");
      });
}

Slam3dOptions load_slam3d_options(const std::string& path, const Slam3dOptions& base) {
  return parse_slam3d_options(config::read_text_file(path), path, base);
}

std::string dump_slam3d_options(const Slam3dOptions& options) {
  return "# lookahead slam3d defaults (lookahead config dump slam3d)\n" +
         config::dump_options(options, [](Slam3dOptions& o, auto& v) { visit_sections(o, v); });
}

}  // namespace lookahead::slam
