// SPDX-License-Identifier: MIT
// `lookahead slam3d INPUT --method rbpf|segslam --out DIR`: 3D mapping with the octree RBPF
// or SegSLAM on octree submaps (slam3d_segslam.hpp). INPUT is
// `garage` (a generated two-level garage), `geb079` (the real Freiburg 079 OctoMap) or a
// folder of 3DTK scans. Writes map.bt, trajectory.png, trajectory.txt and run.json (and
// world.bt for a generated world).
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "lookahead/slam/eval/octree_map_entropy.hpp"
#include "lookahead/slam/io/map_picture.hpp"
#include "lookahead/slam/octree/octree_io.hpp"
#include "lookahead/slam/octree/octree_top_view.hpp"
#include "lookahead/slam/rbpf3d/rbpf3d.hpp"
#include "lookahead/slam/rbpf3d/slam3d_config.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"
#include "slam3d_segslam.hpp"

namespace lookahead::app {
namespace {

struct Slam3dArgs {
  std::string input = "garage";
  std::string method = "rbpf";
  std::string out = "out/slam3d";
  std::string config;
  std::string geb079 = "../shared/data/3d/octomap_share_data/geb079.bt";
  int particles = -1;
  long long seed = -1;
  long long data_seed = 1;
  int threads = -1;
  std::size_t max_sweeps = 0;
  std::string segslam_config;         ///< --method segslam: YAML on top of segslam3d_defaults()
  int map_samples = -1;               ///< --method segslam: offline samples (-1: the config's)
  double max_search_radius = -1.0;    ///< --method segslam: reach cap (< 0: the default)
  double wide_reentry_radius = -1.0;  ///< --method segslam: wide search cap (0: off, < 0: the default)
  bool search_per_particle = false;   ///< --method segslam: no search shared by a segment's copies
};

struct Input {
  slam::RangeLog3 log;
  std::optional<slam::World3> world;  ///< simulated inputs only
};

Input read_input(const Slam3dArgs& a, const slam::Slam3dOptions& o) {
  Input in;
  if (a.input == "garage" || a.input == "geb079") {
    spdlog::info("building the {} world", a.input);
    in.world = a.input == "garage"
                   ? slam::make_garage_world(static_cast<std::uint64_t>(a.data_seed), o.world_resolution)
                   : slam::load_geb079_world(a.geb079);
    std::optional<ProgressBar> bar;  // the simulator knows the sweep count once it starts
    in.log = slam::simulate_cave_crawler(*in.world, o.robot, static_cast<std::uint64_t>(a.data_seed), a.max_sweeps,
                                         [&](std::size_t done, std::size_t total) {
                                           if (!bar) bar.emplace("simulate", total);
                                           bar->update(done);
                                         });
    if (bar) bar->finish();
  } else if (std::filesystem::is_directory(a.input)) {
    in.log = slam::read_3dtk_folder(a.input, o.threedtk);
  } else {
    throw std::runtime_error(a.input + ": expected garage, geb079 or a folder of 3DTK scans");
  }
  if (a.max_sweeps > 0 && in.log.sweeps.size() > a.max_sweeps) in.log.sweeps.resize(a.max_sweeps);
  if (in.log.sweeps.empty()) throw std::runtime_error(a.input + ": no sweeps");
  return in;
}

/// A short name for titles: the folder's own name for a 3DTK folder.
std::string input_name(const std::string& input) {
  std::filesystem::path p = std::filesystem::path(input).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().string();
}

std::vector<slam::Pose2> top_down(const std::vector<slam::Pose3>& poses) {
  std::vector<slam::Pose2> out;
  for (const slam::Pose3& p : poses)
    out.push_back({p.translation().x(), p.translation().y(), slam::euler_of(p.linear()).yaw});
  return out;
}

nlohmann::json memory_json(const slam::Rbpf3d& filter) {
  std::vector<const slam::EvidenceOctree*> maps;
  double unique = 0, total = 0;
  for (const auto& p : filter.particles()) {
    const slam::OctreeMemory m = p.map.memory();
    unique += static_cast<double>(m.unique_bytes);
    total += static_cast<double>(m.total_bytes);
    maps.push_back(&p.map);
  }
  const double n = static_cast<double>(maps.size());
  const double distinct = static_cast<double>(slam::EvidenceOctree::distinct_bytes(maps));
  nlohmann::json j;
  j["mean_map_bytes"] = total / n;              // what one map would cost alone
  j["mean_unique_bytes_per_map"] = unique / n;  // what only that particle holds
  j["all_maps_distinct_bytes"] = distinct;      // the whole population, shared once
  j["distinct_bytes_per_particle"] = distinct / n;
  j["sharing_factor"] = total / distinct;  // N full maps / what is stored
  return j;
}

void write_outputs(const Slam3dArgs& a, const Input& in, const slam::Rbpf3d& filter, double wall_s) {
  std::filesystem::create_directories(a.out);
  const std::size_t best = filter.best_particle();
  const slam::EvidenceOctree& map = filter.particles()[best].map;
  slam::write_octomap(map, a.out + "/map.bt");
  if (in.world && a.input == "garage") slam::write_octomap(in.world->map, a.out + "/world.bt");
  const std::vector<slam::Pose3> estimate = filter.trajectory(best);
  std::vector<slam::Pose3> odometry, truth;
  for (const auto& s : in.log.sweeps) {
    odometry.push_back(s.odometry);
    if (s.truth) truth.push_back(*s.truth);
  }
  std::vector<slam::PicturePath> paths;
  if (!truth.empty()) paths.push_back({top_down(truth), {40, 160, 40}, "ground truth", 2});
  paths.push_back({top_down(odometry), {230, 140, 20}, "dead reckoning", 1});
  paths.push_back({top_down(estimate), {200, 30, 30}, "RBPF estimate (best particle)", 2});
  slam::write_map_picture(
      a.out + "/trajectory.png", slam::top_view(map), paths,
      fmt::format("slam3d {} - rbpf, {} particles (top view)", input_name(a.input), filter.particles().size()));
  std::ofstream traj(a.out + "/trajectory.txt");
  traj << "# t x y z roll pitch yaw (best particle, one line per sweep)\n";
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const slam::Euler e = slam::euler_of(estimate[i].linear());
    const Eigen::Vector3d& p = estimate[i].translation();
    traj << fmt::format("{:.3f} {:.4f} {:.4f} {:.4f} {:.5f} {:.5f} {:.5f}\n", in.log.sweeps[i].time, p.x(), p.y(),
                        p.z(), e.roll, e.pitch, e.yaw);
  }
  const auto& st = filter.statistics();
  nlohmann::json j;
  j["input"] = a.input;
  j["method"] = a.method;
  j["particles"] = filter.particles().size();
  j["seed"] = filter.options().seed;
  j["data_seed"] = a.data_seed;
  j["sweeps"] = st.sweeps;
  j["rays_per_sweep"] = in.log.sweeps.front().rays.size();
  j["resamplings"] = st.resamplings;
  j["wall_time_s"] = wall_s;
  j["predict_weight_s"] = st.predict_weight_seconds;
  j["insert_s"] = st.insert_seconds;
  j["peak_memory_mb"] = peak_memory_mb();
  j["memory"] = memory_json(filter);
  j["map_known_voxels"] = map.known_voxels();
  // SegSLAM eq. (22) of the best particle's map, to compare with SegSLAM's minimum-entropy map sample.
  j["map_entropy_nats_m3"] = slam::octree_map_entropy(map);
  if (!truth.empty()) {
    const Eigen::Vector3d& end = truth.back().translation();
    double length = 0;
    for (std::size_t i = 1; i < truth.size(); ++i)
      length += (truth[i].translation() - truth[i - 1].translation()).norm();
    j["path_length_m"] = length;
    j["final_position_error_m"] = (filter.mean_position() - end).norm();
    j["final_position_error_best_particle_m"] = (estimate.back().translation() - end).norm();
    j["dead_reckoning_final_error_m"] = (odometry.back().translation() - end).norm();
  }
  j["neff_history"] = st.neff;
  write_run_json(a.out, j, filter.options().threads, a.config);
  if (j.contains("final_position_error_m")) {
    spdlog::info("final position error {:.2f} m (dead reckoning {:.2f} m) over {:.0f} m",
                 j["final_position_error_m"].get<double>(), j["dead_reckoning_final_error_m"].get<double>(),
                 j["path_length_m"].get<double>());
  }
}

slam::Slam3dOptions options_from(const Slam3dArgs& a) {
  slam::Slam3dOptions o;
  if (!a.config.empty()) o = slam::load_slam3d_options(a.config);
  if (a.particles >= 0) o.filter.particles = a.particles;
  if (a.seed >= 0) o.filter.seed = static_cast<std::uint64_t>(a.seed);
  if (a.threads >= 0) o.filter.threads = a.threads;
  o.filter.validate();
  return o;
}

int run_slam3d(const Slam3dArgs& a) {
  const slam::Slam3dOptions options = options_from(a);
  const Input in = read_input(a, options);
  if (a.method == "segslam") {
    run_segslam3d({a.input, input_name(a.input), a.out, a.segslam_config, a.map_samples, a.data_seed,
                   a.max_search_radius, a.wide_reentry_radius, a.search_per_particle},
                  in.log, options);
    if (in.world && a.input == "garage") slam::write_octomap(in.world->map, a.out + "/world.bt");
    return 0;
  }
  spdlog::info("{} sweeps, {} beams each; {} particles, {:.2f} m voxels", in.log.sweeps.size(),
               in.log.sweeps.front().rays.size(), options.filter.particles, options.filter.map.resolution);
  slam::Rbpf3d filter(options.filter);
  ProgressBar bar("slam3d", in.log.sweeps.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < in.log.sweeps.size(); ++i) {
    filter.add_sweep(in.log.sweeps[i]);
    const auto& neff = filter.statistics().neff;
    bar.update(i + 1, neff.empty() ? "" : fmt::format("Neff {:.0f}", neff.back()));
  }
  bar.finish();
  const double wall = seconds_since(start);
  Slam3dArgs with_yaml = a;
  with_yaml.config = slam::dump_slam3d_options(options);
  write_outputs(with_yaml, in, filter, wall);
  spdlog::info("done in {:.1f} s, peak {:.0f} MB; wrote {}/trajectory.png and map.bt", wall, peak_memory_mb(), a.out);
  return 0;
}

}  // namespace

Run add_slam3d_command(CLI::App& app) {
  auto args = std::make_shared<Slam3dArgs>();
  app.add_option("input", args->input, "garage | geb079 | a folder of 3DTK scanNNN.3d/.pose")->capture_default_str();
  app.add_option("--method", args->method, "rbpf | segslam")
      ->check(CLI::IsMember({"rbpf", "segslam"}))
      ->capture_default_str();
  app.add_option("--out", args->out, "output folder")->capture_default_str();
  app.add_option("--config", args->config, "YAML options (see config/slam3d/default.yaml)");
  app.add_option("--geb079", args->geb079, "path of geb079.bt")->capture_default_str();
  app.add_option("--particles", args->particles, "number of particles (overrides the config)");
  app.add_option("--seed", args->seed, "filter seed (overrides the config)");
  app.add_option("--data-seed", args->data_seed, "seed of the simulated world and robot")->capture_default_str();
  app.add_option("--threads", args->threads, "worker threads, 0 = all cores");
  app.add_option("--max-sweeps", args->max_sweeps, "stop after this many sweeps (0 = all)");
  app.add_option("--segslam-config", args->segslam_config,
                 "--method segslam: SegSLAM YAML (defaults: lookahead config dump segslam3d)");
  app.add_option("--map-samples", args->map_samples,
                 "--method segslam: offline map samples for the min-entropy map.bt");
  app.add_option("--max-search-radius", args->max_search_radius,
                 "--method segslam: cap of the re-entry search's reach [m], which widens with the motion error "
                 "since the candidate (default 6; 0 keeps the fixed 2 m search)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--wide-reentry-radius", args->wide_reentry_radius,
                 "--method segslam: cap of the wide re-entry search beyond that reach [m], sized by SegSLAM eq. (18)'s "
                 "sigma_tau and taken only when one pose of it fits (default 25; 0: off)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--search-per-particle", args->search_per_particle,
               "--method segslam: every particle searches its own copy of a candidate segment (default: the "
               "copies of one segment share the searches that find nothing; matches are fitted per copy)");
  return [args] { return run_slam3d(*args); };
}

}  // namespace lookahead::app
