// SPDX-License-Identifier: MIT
// `lookahead slam LOG --out DIR`: maps a laser log and writes map.pgm/.yaml, map.png,
// trajectory.txt and run.json.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "log_input.hpp"
#include "lookahead/pipeline/pslam_config.hpp"
#include "lookahead/pipeline/slam_lookahead.hpp"
#include "lookahead/slam/eval/map_entropy.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/io/map_picture.hpp"
#include "lookahead/slam/io/odometry_check.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"
#include "slam_hybrid.hpp"
#include "slam_segslam.hpp"

namespace lookahead::app {
namespace {

// The real one-loop laser log that Debian's mrpt-common ships: no download needed.
constexpr const char* kDefaultLog = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

struct SlamArgs {
  std::string log = kDefaultLog;
  std::string out = "out/slam";
  std::string config;
  int particles = -1;
  long long seed = -1;
  int threads = -1;
  std::size_t max_scans = 0;
  bool skip_bad_lines = false;
  slam::BagReadOptions bag;
  bool predict = false;
  std::string method = "rbpf";
  std::string segslam_config;
  int map_samples = -1;
};

// The RBPF's and the predictor's options of --config, with the command line's overrides.
pipeline::PslamOptions options_from(const SlamArgs& a) {
  pipeline::PslamOptions file = pipeline::load_pslam_options(a.config);
  slam::RbpfOptions& o = file.rbpf;
  if (a.particles >= 0) o.particles = a.particles;
  if (a.seed >= 0) o.seed = static_cast<std::uint64_t>(a.seed);
  if (a.threads >= 0) o.threads = a.threads;
  if (a.predict) o.prediction.enabled = true;
  return file;
}

nlohmann::json prediction_json(const slam::RbpfStatistics& st, const pipeline::SlamLookaheadStatistics& p,
                               const pipeline::LogPredictionOptions& options) {
  nlohmann::json records = nlohmann::json::array();
  for (const auto& r : p.records) {
    records.push_back({{"update", r.update},
                       {"x", r.x},
                       {"y", r.y},
                       {"status", predictor::to_string(r.status)},
                       {"psi", r.psi},
                       {"conflict_share", r.conflict_share},
                       {"predicted_area_m2", r.predicted_area}});
  }
  return {{"requests", p.requests},
          {"hypotheses", p.hypotheses},
          {"no_control_point", p.no_control_point},
          {"no_match", p.no_match},
          {"prediction_wall_time_s", p.seconds},
          {"predicted_updates", st.predicted_updates},
          {"used", st.prediction_used},
          {"rejected_by_hit_ratio", st.prediction_rejected},
          {"records", records},
          {"options_yaml", pipeline::dump_log_prediction_options(options)}};
}

// With --predict, map.png marks every prediction's target by what became of it (in the
// map frame of the best particle when it was made).
std::vector<slam::PicturePoints> prediction_targets(const pipeline::SlamLookaheadStatistics& p) {
  slam::PicturePoints made{{}, {30, 80, 220}, "prediction target: hypothesis made", 6};
  slam::PicturePoints no_match{{}, {240, 150, 0}, "... no match above the threshold", 4};
  slam::PicturePoints no_corner{{}, {150, 150, 150}, "... no control point", 3};
  for (const auto& r : p.records) {
    auto& set = r.status == predictor::Prediction::Status::kPredicted ? made
                : r.status == predictor::Prediction::Status::kNoMatch ? no_match
                                                                      : no_corner;
    set.points.emplace_back(r.x, r.y);
  }
  return {no_corner, no_match, made};
}

void write_outputs(const SlamArgs& a, const slam::LaserLog& log, const slam::Rbpf& filter, double wall_s,
                   const pipeline::SlamLookahead* lookahead, const pipeline::LogPredictionOptions& prediction) {
  std::filesystem::create_directories(a.out);
  const auto& best = filter.particles()[filter.best_particle()];
  const slam::ProbabilityMap map = slam::to_probability_map(best.map);
  slam::write_map(map, a.out, "map");
  const std::vector<slam::Pose2> path = filter.best_trajectory();
  std::vector<slam::StampedPose> stamped;
  for (std::size_t i = 0; i < path.size(); ++i) stamped.push_back({filter.timestamps()[i], path[i]});
  slam::write_trajectory(a.out + "/trajectory.txt", stamped);
  slam::write_tum_trajectory(a.out + "/trajectory.tum", stamped);  // for evo
  // CARMEN logs carry a second clock; GMapping's corrected logs print that one, so a copy on
  // it lets `lookahead eval --reference-log X.gfs.log` pair the poses.
  if (std::any_of(log.scans.begin(), log.scans.end(),
                  [](const auto& s) { return s.logger_timestamp != s.timestamp; })) {
    for (std::size_t i = 0; i < stamped.size(); ++i) stamped[i].t = log.scans[i].logger_timestamp;
    slam::write_trajectory(a.out + "/trajectory_logger_time.txt", stamped);
  }
  slam::write_map_picture(
      a.out + "/map.png", map,
      {{filter.odometry(), {230, 140, 20}, "odometry", 1}, {path, {200, 30, 30}, "RBPF estimate (best particle)", 2}},
      std::filesystem::path(log.path).filename().string(),
      lookahead ? prediction_targets(lookahead->statistics()) : std::vector<slam::PicturePoints>{});
  const auto& st = filter.statistics();
  const slam::MapEntropy h = slam::map_entropy(map);
  nlohmann::json j;
  j["log"] = log.path;
  j["scans"] = st.scans;
  j["bad_lines_skipped"] = log.bad_lines;
  j["stopped_early"] = log.stopped_early;  // empty: the whole log was read
  j["odometry_jumps"] = log.odometry_jumps.count;
  j["scans_skipped"] = log.non_finite.count + log.time_reversals.count;
  j["updates"] = st.updates;
  j["resamplings"] = st.resamplings;
  j["scan_match_failures"] = st.match_failures;
  j["particle_updates"] = st.particle_updates;
  j["wall_time_s"] = wall_s;
  j["log_duration_s"] = log.scans.empty() ? 0.0 : log.scans.back().timestamp - log.scans.front().timestamp;
  j["peak_memory_mb"] = peak_memory_mb();
  j["neff_history"] = st.neff;
  const slam::Pose2 mean = filter.mean_pose();
  j["final_estimate"] = {mean.x, mean.y, mean.theta};  // weighted mean, as SegSLAM's run.json
  j["map_entropy_nats"] = h.total;
  j["map_observed_cells"] = h.observed;
  if (lookahead) j["prediction"] = prediction_json(st, lookahead->statistics(), prediction);
  write_run_json(a.out, j, filter.options().threads,
                 slam::dump_rbpf_options(filter.options()) + pipeline::dump_log_prediction_options(prediction));
}

int run_slam(const SlamArgs& a) {
  // --config is a HybridSLAM YAML with --method hybrid, read in run_slam_hybrid.
  const pipeline::PslamOptions file = a.method == "hybrid" ? pipeline::PslamOptions{} : options_from(a);
  const slam::RbpfOptions& options = file.rbpf;
  slam::LogReadOptions read;
  read.skip_bad_lines = a.skip_bad_lines;
  read.bag = a.bag;
  slam::LaserLog log = load_laser_log(a.log, read, a.max_scans);
  if (a.method == "hybrid") return run_slam_hybrid(log, {a.out, a.config, a.particles, a.seed});
  spdlog::info("{} scans, {} beams each; {} particles", log.scans.size(), log.scans.front().ranges.size(),
               options.particles);
  slam::Rbpf filter(options);
  // P-SLAM: predictions of the region ahead enter the weights (off: plain RBPF, bit for bit).
  const pipeline::LogPredictionOptions& prediction = file.prediction;
  std::unique_ptr<pipeline::SlamLookahead> lookahead;
  if (options.prediction.enabled) {
    lookahead = std::make_unique<pipeline::SlamLookahead>(prediction.predictor, prediction.targets);
  }
  ProgressBar bar("slam", log.scans.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    if (filter.add_scan(log.scans[i]) && lookahead) lookahead->after_update(filter);
    const auto& neff = filter.statistics().neff;
    bar.update(i + 1, neff.empty() ? "" : fmt::format("Neff {:.0f}", neff.back()));
  }
  bar.finish();
  const double wall = seconds_since(start);
  write_outputs(a, log, filter, wall, lookahead.get(), prediction);
  spdlog::info("done in {:.1f} s ({:.1f}x real time), peak {:.0f} MB; wrote {}/map.png", wall,
               (log.scans.back().timestamp - log.scans.front().timestamp) / wall, peak_memory_mb(), a.out);
  return 0;
}

}  // namespace

Run add_slam_command(CLI::App& app) {
  auto args = std::make_shared<SlamArgs>();
  app.add_option("log", args->log, "CARMEN log (.log/.clf, .gz), MRPT .rawlog or ROS1 .bag")
      ->default_str("the MRPT one-loop dataset");
  app.add_option("--out", args->out, "output folder")->capture_default_str();
  app.add_option("--config", args->config, "YAML options (see config/slam/default.yaml)");
  app.add_option("--particles", args->particles, "number of particles (overrides the config)");
  app.add_option("--seed", args->seed, "random seed (overrides the config)");
  app.add_option("--threads", args->threads, "worker threads, 0 = all cores");
  app.add_option("--max-scans", args->max_scans, "stop after this many scans (0 = all)");
  app.add_flag("--skip-bad-lines", args->skip_bad_lines, "count and skip malformed log lines");
  add_bag_options(app, args->bag);
  app.add_flag("--predict", args->predict, "P-SLAM: predict the region ahead and use it in the weights");
  app.add_option("--method", args->method,
                 "rbpf (grid RBPF), segslam (segmented RBPF with submaps) or hybrid (HybridSLAM landmarks; "
                 "--config then takes a hybrid YAML)")
      ->check(CLI::IsMember({"rbpf", "segslam", "hybrid"}))
      ->capture_default_str();
  app.add_option("--segslam-config", args->segslam_config, "SegSLAM YAML options (see config/segslam/default.yaml)");
  app.add_option("--map-samples", args->map_samples,
                 "SegSLAM: map samples of the minimum-entropy search (0: the best particle's chain alone)");
  return [args] {
    if (args->method == "segslam") {
      return run_segslam({args->log, args->out, args->config, args->segslam_config, args->particles, args->seed,
                          args->threads, args->max_scans, args->skip_bad_lines, args->map_samples, args->bag});
    }
    return run_slam(*args);
  };
}

}  // namespace lookahead::app
