// SPDX-License-Identifier: MIT
#include "slam_segslam.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "log_input.hpp"
#include "lookahead/pipeline/pslam_config.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/odometry_check.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"
#include "lookahead/slam/rbpf/slam_config.hpp"
#include "lookahead/slam/segslam/min_entropy_search.hpp"
#include "lookahead/slam/segslam/seg_slam.hpp"
#include "lookahead/slam/segslam/segment_picture.hpp"
#include "lookahead/slam/segslam/segslam_config.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"

namespace lookahead::app {
namespace {

using slam::segslam::SegSlam;

slam::LaserLog read_log(const SegSlamArgs& a) {
  slam::LogReadOptions read;
  read.skip_bad_lines = a.skip_bad_lines;
  read.bag = a.bag;
  return load_laser_log(a.log, read, a.max_scans);
}

// NAME.txt (the log's time stamps) and NAME_logger_time.txt (the logger's, for lookahead eval
// --reference-log): one pose per scan.
void write_trajectory_files(const std::string& out, const std::string& name, const slam::LaserLog& log,
                            const std::vector<slam::Pose2>& path) {
  std::vector<slam::StampedPose> stamped, logger;
  for (std::size_t i = 0; i < path.size(); ++i) {
    stamped.push_back({log.scans[i].timestamp, path[i]});
    logger.push_back({log.scans[i].logger_timestamp, path[i]});
  }
  slam::write_trajectory(out + "/" + name + ".txt", stamped);
  slam::write_tum_trajectory(out + "/" + name + ".tum", stamped);  // for evo
  slam::write_trajectory(out + "/" + name + "_logger_time.txt", logger);
}

nlohmann::json statistics_json(const SegSlam& filter) {
  const auto& st = filter.statistics();
  nlohmann::json j;
  j["scans"] = st.scans;
  j["updates"] = st.updates;
  j["resamplings"] = st.resamplings;
  j["scan_match_failures"] = st.match_failures;
  j["segmentations"] = st.segmentations;
  j["matches"] = st.matches;
  j["match_attempts"] = st.match_attempts;
  j["pruned_submaps"] = st.pruned;
  j["live_submaps"] = filter.segmap().live_count();
  j["locked_submaps"] = st.locked;
  j["merged_submaps"] = st.merged;
  j["submaps_with_maps"] = filter.segmap().map_count();
  j["segments"] = filter.segmap().segment_count();
  j["neff_history"] = st.neff;
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : st.match_events)
    events.push_back({{"scan", e.scan}, {"candidate", e.candidate}, {"weight", e.weight}});
  j["match_events"] = events;
  return j;
}

}  // namespace

int run_segslam(const SegSlamArgs& a) {
  slam::RbpfOptions rbpf = pipeline::load_pslam_options(a.config).rbpf;
  if (a.particles >= 0) rbpf.particles = a.particles;
  if (a.seed >= 0) rbpf.seed = static_cast<std::uint64_t>(a.seed);
  if (a.threads >= 0) rbpf.threads = a.threads;
  slam::segslam::SegSlamOptions options;
  if (!a.segslam_config.empty()) options = slam::load_segslam_options(a.segslam_config);
  if (a.map_samples >= 0) {
    options.offline.map_samples = a.map_samples;
    slam::segslam::validate(options);  // 0 only with offline.particle_chain
  }
  spdlog::info("reading {}", a.log);
  const slam::LaserLog log = read_log(a);
  spdlog::info("{} scans; SegSLAM with {} particles, look-ahead {} s", log.scans.size(), rbpf.particles,
               options.segmentation.lookahead_s);
  SegSlam filter(rbpf, options);
  ProgressBar bar("segslam", log.scans.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    filter.add_scan(log.scans[i]);
    bar.update(i + 1,
               fmt::format("{} segments, {} matches", filter.segmap().segment_count(), filter.statistics().matches));
  }
  filter.finish();
  bar.finish();
  const double filter_s = seconds_since(start);
  // Offline (SegSLAM sec. 5.4): many map samples, keep the one of least entropy.
  const auto offline_start = std::chrono::steady_clock::now();
  const auto best = slam::segslam::min_entropy_search(filter, options.offline.map_samples, rbpf.seed, rbpf.threads);
  const double offline_s = seconds_since(offline_start);

  std::filesystem::create_directories(a.out);
  slam::write_map(best.best.map, a.out, "map");
  write_trajectory_files(a.out, "trajectory", log, filter.trajectory_at_every_scan(filter.best_particle()));
  // The path the map was pasted from (bench/runs/csail_error.py --global scores maps by it).
  write_trajectory_files(a.out, "map_trajectory", log,
                         slam::segslam::sample_trajectory_at_every_scan(filter, best.best));
  std::vector<slam::Pose2> odometry;
  for (const auto& s : log.scans) odometry.push_back(s.odometry);
  // The paths of the submaps the map was pasted from, so the picture's path and walls agree.
  slam::segslam::write_segment_picture(
      a.out + "/map.png", best.best.map, odometry, slam::segslam::sample_paths(filter, best.best),
      std::filesystem::path(log.path).filename().string() + " - SegSLAM, min-entropy map" +
          (best.best.chain ? " (the best particle's chain)" : ""));
  const slam::Pose2 final_pose = filter.estimate();
  nlohmann::json j = statistics_json(filter);
  j["log"] = log.path;
  j["method"] = "segslam";
  j["particles"] = rbpf.particles;
  j["wall_time_s"] = filter_s;
  j["offline_search_s"] = offline_s;
  j["log_duration_s"] = log.scans.back().timestamp - log.scans.front().timestamp;
  j["peak_memory_mb"] = peak_memory_mb();
  j["final_estimate"] = {final_pose.x, final_pose.y, final_pose.theta};
  j["map_samples"] = best.entropies.size();
  j["map_sample_entropies"] = best.entropies;
  j["min_entropy_nats_m2"] = best.best.entropy;
  j["chain_entropy_nats_m2"] = best.chain_entropy;  // 0 with offline.particle_chain off
  j["map_is_particle_chain"] = best.best.chain;
  j["map_particle"] = best.best.particle;
  write_run_json(a.out, j, rbpf.threads,
                 slam::dump_rbpf_options(rbpf) + "segslam:\n" + indent(slam::dump_segslam_options(options)));
  spdlog::info(
      "done: filter {:.1f} s, offline search {:.1f} s ({} samples{}, min entropy {:.1f}{}); {} segments, {} matches; "
      "wrote {}/map.png",
      filter_s, offline_s, best.entropies.size(),
      options.offline.particle_chain ? " and the best particle's chain" : "", best.best.entropy,
      best.best.chain ? ", the chain's" : "", filter.segmap().segment_count(), filter.statistics().matches, a.out);
  return 0;
}

}  // namespace lookahead::app
