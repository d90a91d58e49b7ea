// SPDX-License-Identifier: MIT
#include "slam3d_segslam.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "lookahead/slam/eval/absolute_error.hpp"
#include "lookahead/slam/octree/octree_io.hpp"
#include "lookahead/slam/octree/octree_top_view.hpp"
#include "lookahead/slam/segslam/octree_map_samples.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/segslam/segslam_config.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"

namespace lookahead::app {
namespace {

using slam::segslam::SegSlam3d;

/// Bytes of the particles' open maps and of every map the filter holds (open and stored
/// submaps), each shared node counted once.
nlohmann::json memory_json(const SegSlam3d& f) {
  std::vector<const slam::EvidenceOctree*> all;
  double unique = 0, total = 0;
  for (const auto& p : f.particles()) {
    const slam::OctreeMemory m = p.submap.map.memory();
    unique += static_cast<double>(m.unique_bytes);
    total += static_cast<double>(m.total_bytes);
    all.push_back(&p.submap.map);
  }
  for (std::size_t id = 0; id < f.segmap().id_bound(); ++id) {
    if (f.segmap().contains(id)) all.push_back(&f.segmap().at(id).map);
  }
  const double n = static_cast<double>(f.particles().size());
  const double distinct = static_cast<double>(slam::EvidenceOctree::distinct_bytes(all));
  nlohmann::json j;
  j["mean_open_submap_bytes"] = total / n;
  j["mean_unique_bytes_per_map"] = unique / n;  // what only that particle's open submap holds
  j["all_maps_distinct_bytes"] = distinct;      // open and stored submaps, shared once
  j["distinct_bytes_per_particle"] = distinct / n;
  return j;
}

void write_trajectory(const std::string& path, const slam::RangeLog3& log, const std::vector<slam::Pose4>& poses) {
  std::ofstream traj(path);
  traj << "# t x y z roll pitch yaw (best particle's reconstructed trajectory, eq. 11; roll, pitch: IMU)\n";
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const slam::Euler imu = slam::euler_of(log.sweeps[i].odometry.linear());
    traj << fmt::format("{:.3f} {:.4f} {:.4f} {:.4f} {:.5f} {:.5f} {:.5f}\n", log.sweeps[i].time, poses[i].x,
                        poses[i].y, poses[i].z, imu.roll, imu.pitch, poses[i].yaw);
  }
}

/// A match event, and with ground truth how far its claim (where the robot is relative to
/// the candidate's nearest path pose) is from the truth: the check of a re-entry.
nlohmann::json match_json(const slam::segslam::MatchEvent3& e, const slam::RangeLog3& log) {
  nlohmann::json j{{"sweep", e.sweep},
                   {"candidate", e.candidate},
                   {"weight", e.weight},
                   {"icp_error_m", e.icp_error},
                   {"all_points_error_m", e.all_points_error},
                   {"translation_m", e.translation},
                   {"pose", {e.pose.x, e.pose.y, e.pose.z, e.pose.yaw}},
                   {"reference_sweep", e.reference_sweep},
                   {"chosen", e.chosen},
                   {"structure_points", e.structure.points},
                   {"structure_inlier_ratio", e.structure.inlier_ratio},
                   {"structure_error_m", e.structure.mean_error},
                   {"structure_free_ratio", e.structure.free_ratio}};
  if (!log.has_truth()) return j;
  const slam::Pose4 truth = slam::Pose4::level_of(*log.sweeps.at(e.reference_sweep).truth)
                                .between(slam::Pose4::level_of(*log.sweeps.at(e.sweep).truth));
  const slam::Pose4 off = truth.between(e.reference.between(e.pose));
  const slam::Pose4 guess_off = truth.between(e.reference.between(e.guess));
  j["truth_position_error_m"] = off.position().norm();
  j["truth_offset"] = {off.x, off.y, off.z, off.yaw};  // the claim against the truth, in the truth's reference frame
  j["truth_yaw_error_rad"] = off.yaw;
  j["guess_truth_position_error_m"] = guess_off.position().norm();
  j["guess_truth_yaw_error_rad"] = guess_off.yaw;
  return j;
}

/// A candidate considered for a re-entry, and with ground truth how far the map sample's
/// guess is from the truth (relative to the candidate's path pose nearest the guess) and how
/// near the robot truly is to where the candidate was mapped (same deck): was the right
/// re-entry within reach, and what became of it. Also written to the debug log.
nlohmann::json attempt_json(const slam::segslam::MatchAttempt3& a, const slam::RangeLog3& log) {
  nlohmann::json j{{"sweep", a.sweep},
                   {"particle", a.particle},
                   {"candidate", a.candidate},
                   {"outcome", slam::segslam::name_of(a.outcome)},
                   {"rejection", a.rejection},
                   {"path_distance_m", a.path_distance},
                   {"match_path_distance_m", a.match_path_distance},
                   {"proximity_radius_m", a.proximity_radius},
                   {"search_radius_m", a.search_radius},
                   {"search_angle_rad", a.search_angle},
                   {"error_since_m", a.error_since},
                   {"chain_error_m", a.chain_error},
                   {"wide_proximity_radius_m", a.wide_proximity_radius},
                   {"wide_search_radius_m", a.wide_search_radius},
                   {"wide_search_angle_rad", a.wide_search_angle},
                   {"wide", a.wide},
                   {"modes", a.modes},
                   {"confirmation", a.confirmation},
                   {"guess_score", a.guess_score},
                   {"coarse_score", a.coarse_score},
                   {"reference_sweep", a.reference_sweep},
                   {"guess", {a.guess.x, a.guess.y, a.guess.z, a.guess.yaw}}};
  std::string truth;
  if (log.has_truth()) {
    const auto level = [&](std::size_t s) { return slam::Pose4::level_of(*log.sweeps.at(s).truth); };
    const slam::Pose4 off = level(a.reference_sweep).between(level(a.sweep)).between(a.reference.between(a.guess));
    const slam::Pose4 now = level(a.sweep);
    double near = std::numeric_limits<double>::infinity();
    for (const auto& [first, last] : a.intervals) {
      for (std::size_t s = first; s <= last && s < log.sweeps.size(); ++s) {
        const slam::Pose4 q = level(s);
        if (std::abs(q.z - now.z) <= 1.0) near = std::min(near, std::hypot(q.x - now.x, q.y - now.y));
      }
    }
    j["guess_truth_position_error_m"] = off.position().norm();
    j["guess_truth_yaw_error_rad"] = off.yaw;
    j["guess_truth_height_error_m"] = off.z;
    j["truth_distance_to_candidate_path_m"] = near;
    truth = fmt::format(", guess {:.2f} m / {:.3f} rad from the truth, robot truly {:.1f} m from the candidate's path",
                        off.position().norm(), off.yaw, near);
  }
  spdlog::debug(
      "match attempt: sweep {} particle {} candidate {}: {}{}{}; guess {:.1f} m from its path (radius {:.1f} m, "
      "search +-{:.1f} m), coarse score {:.2f} -> {:.2f}{}",
      a.sweep, a.particle, a.candidate, slam::segslam::name_of(a.outcome), *a.rejection ? ": " : "", a.rejection,
      a.path_distance, a.proximity_radius, a.search_radius, a.guess_score, a.coarse_score, truth);
  return j;
}

nlohmann::json statistics_json(const SegSlam3d& f, const slam::RangeLog3& log) {
  const auto& st = f.statistics();
  nlohmann::json j;
  j["sweeps"] = st.sweeps;
  j["updates"] = st.updates;
  j["resamplings"] = st.resamplings;
  j["segmentations"] = st.segmentations;
  j["matches"] = st.matches;
  j["match_attempts"] = st.match_attempts;
  j["match_requests"] = st.match_requests;
  j["wide_match_attempts"] = st.wide_attempts;
  j["capped_searches"] = st.capped_searches;  // grouped: each answers several of match_attempts
  j["matching_thread_s"] = st.matching_seconds;
  j["wide_matching_thread_s"] = st.wide_matching_seconds;
  j["pruned_submaps"] = st.pruned;
  j["live_submaps"] = f.segmap().live_count();
  j["segments"] = f.segmap().segment_count();
  // Locking and merging (SegSLAM sec. 6; the `locking:` keys of --segslam-config, off by default).
  j["locked_submaps"] = st.locked;
  j["locked_particle_updates"] = st.locked_updates;  // particle steps without ray insertion
  j["merged_submaps"] = st.merged;
  j["submaps_with_maps"] = f.segmap().map_count();
  nlohmann::json events = nlohmann::json::array(), offers = nlohmann::json::array();
  for (const auto& e : st.match_events) events.push_back(match_json(e, log));
  for (const auto& e : st.match_offers) offers.push_back(match_json(e, log));
  j["match_events"] = events;
  j["match_offers"] = offers;
  if (!st.attempts.empty()) {
    nlohmann::json attempts = nlohmann::json::array();
    for (const auto& a : st.attempts) attempts.push_back(attempt_json(a, log));
    j["match_attempt_log"] = attempts;
  }
  j["neff_history"] = st.neff;
  return j;
}

// RMSE of a path's positions in the plane from the truth after the best SE(2) alignment: how
// consistent a map drawn along that path is (the 2D study's measure, bench/runs/csail_error.py --global).
double aligned_planar_rmse(const slam::RangeLog3& log, const std::vector<slam::Pose4>& path) {
  std::vector<slam::StampedPose> truth, estimate;
  for (std::size_t i = 0; i < log.sweeps.size() && i < path.size(); ++i) {
    truth.push_back({static_cast<double>(i), slam::Pose4::level_of(*log.sweeps[i].truth).planar()});
    estimate.push_back({static_cast<double>(i), path[i].planar()});
  }
  return slam::absolute_trajectory_error(truth, estimate).rmse;
}

void add_errors(nlohmann::json& j, const slam::RangeLog3& log, const SegSlam3d& f,
                const std::vector<slam::Pose4>& best) {
  if (!log.has_truth()) return;
  j["trajectory_aligned_rmse_m"] = aligned_planar_rmse(log, best);
  const Eigen::Vector3d end = log.sweeps.back().truth->translation();
  double length = 0;
  for (std::size_t i = 1; i < log.sweeps.size(); ++i) {
    length += (log.sweeps[i].truth->translation() - log.sweeps[i - 1].truth->translation()).norm();
  }
  j["path_length_m"] = length;
  j["final_position_error_m"] = (f.estimate().position() - end).norm();
  j["final_position_error_best_particle_m"] = (best.back().position() - end).norm();
  j["dead_reckoning_final_error_m"] = (log.sweeps.back().odometry.translation() - end).norm();
}

}  // namespace

void run_segslam3d(const SegSlam3dRun& run, const slam::RangeLog3& log, const slam::Slam3dOptions& o) {
  slam::segslam::SegSlam3dOptions options;
  options.filter = o.filter;
  if (!run.segslam_config.empty()) {
    options.segslam = slam::load_segslam_options(run.segslam_config, slam::segslam::segslam3d_defaults());
  }
  // SPDLOG_LEVEL=debug: every candidate considered is logged and kept in run.json.
  options.extras.record_attempts = spdlog::should_log(spdlog::level::debug);
  if (run.max_search_radius >= 0) options.segslam.matching.max_search_radius = run.max_search_radius;
  if (run.wide_reentry_radius >= 0) options.extras.wide.max_radius = run.wide_reentry_radius;
  if (run.search_per_particle) options.segslam.matching.share_by_segment = false;
  if (run.map_samples >= 0) {
    options.segslam.offline.map_samples = run.map_samples;
    slam::segslam::validate(options.segslam);  // 0 only with offline.particle_chain
  }
  SegSlam3d filter(options);
  ProgressBar bar("segslam3d", log.sweeps.size());
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < log.sweeps.size(); ++i) {
    filter.add_sweep(log.sweeps[i]);
    bar.update(i + 1,
               fmt::format("segs {} matches {}", filter.statistics().segmentations, filter.statistics().matches));
  }
  filter.finish();
  bar.finish();
  const double wall = seconds_since(start);
  const auto search_start = std::chrono::steady_clock::now();
  const int samples = options.segslam.offline.map_samples;
  const auto best_map = slam::segslam::min_entropy_search(filter, samples, options.filter.seed);
  const double search_s = seconds_since(search_start);

  std::filesystem::create_directories(run.out);
  slam::write_octomap(best_map.best.map, run.out + "/map.bt");
  const std::size_t best = filter.best_particle();
  const std::vector<slam::Pose4> poses = filter.trajectory_at_every_sweep(best);
  write_trajectory(run.out + "/trajectory.txt", log, poses);
  std::vector<slam::Pose2> odometry;
  for (const auto& s : log.sweeps) odometry.push_back(slam::Pose4::level_of(s.odometry).planar());
  slam::segslam::write_segment_picture(
      run.out + "/trajectory.png", slam::top_view(best_map.best.map), odometry,
      slam::segslam::sample_paths(filter, best_map.best),
      fmt::format("slam3d {} - segslam, {} particles (top view, min-entropy map{})", run.name,
                  filter.particles().size(), best_map.best.chain ? ": the best particle's chain" : ""));

  nlohmann::json j = statistics_json(filter, log);
  j["input"] = run.input;
  j["method"] = "segslam";
  j["particles"] = filter.particles().size();
  j["seed"] = options.filter.seed;
  j["data_seed"] = run.data_seed;
  j["rays_per_sweep"] = log.sweeps.front().rays.size();
  j["wall_time_s"] = wall;
  j["offline_search_s"] = search_s;
  j["map_samples"] = samples;
  j["max_search_radius"] = options.segslam.matching.max_search_radius;
  j["share_by_segment"] = options.segslam.matching.share_by_segment;
  const auto& wide = options.extras.wide;
  j["wide_reentry"] = {{"max_radius_m", wide.max_radius},
                       {"sigmas", wide.sigmas},
                       {"trigger_sigmas", wide.trigger_sigmas},
                       {"guess_step_m", wide.guess_step},
                       {"guess_angle_step_rad", wide.guess_angle_step},
                       {"angle_per_error_rad_per_m", wide.angle_per_error},
                       {"max_angle_rad", wide.max_angle},
                       {"peaks", wide.peaks},
                       {"separation_m", wide.separation},
                       {"angle_separation_rad", wide.angle_separation},
                       {"confirm_distance_m", wide.confirm_distance},
                       {"confirm_angle_rad", wide.confirm_angle}};
  j["map_entropy_nats_m3"] = best_map.best.entropy;
  j["chain_entropy_nats_m3"] = best_map.chain_entropy;  // 0 with offline.particle_chain off
  j["map_is_particle_chain"] = best_map.best.chain;
  if (log.has_truth()) {
    j["map_path_aligned_rmse_m"] =
        aligned_planar_rmse(log, slam::segslam::sample_trajectory_at_every_sweep(filter, best_map.best));
  }
  j["sample_entropies"] = best_map.entropies;
  j["map_known_voxels"] = best_map.best.map.known_voxels();
  j["peak_memory_mb"] = peak_memory_mb();
  j["memory"] = memory_json(filter);
  add_errors(j, log, filter, poses);
  slam::Slam3dOptions with_filter = o;
  with_filter.filter = options.filter;
  write_run_json(
      run.out, j, with_filter.filter.threads,
      slam::dump_slam3d_options(with_filter) + "segslam:\n" + indent(slam::dump_segslam_options(options.segslam)));
  if (j.contains("final_position_error_m")) {
    spdlog::info(
        "final position error {:.2f} m (dead reckoning {:.2f} m) over {:.0f} m; {} segmentations, {} matches "
        "({} locked, {} merged)",
        j["final_position_error_m"].get<double>(), j["dead_reckoning_final_error_m"].get<double>(),
        j["path_length_m"].get<double>(), filter.statistics().segmentations, filter.statistics().matches,
        filter.statistics().locked, filter.statistics().merged);
  }
  spdlog::info("filter {:.1f} s, offline search {:.1f} s, peak {:.0f} MB; wrote {}/trajectory.png and map.bt", wall,
               search_s, peak_memory_mb(), run.out);
}

}  // namespace lookahead::app
