// SPDX-License-Identifier: MIT
#include "slam_hybrid.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hybrid_pictures.hpp"
#include "lookahead/slam/eval/absolute_error.hpp"
#include "lookahead/slam/eval/relative_error.hpp"
#include "lookahead/slam/eval/scan_matched_reference.hpp"
#include "lookahead/slam/hybrid/hybrid_config.hpp"
#include "lookahead/slam/hybrid/log_mapper.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/io/trajectory_io.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"
#include "process_stats.hpp"
#include "progress_bar.hpp"
#include "run_json.hpp"

namespace lookahead::app {
namespace {

using namespace slam::hybrid;

LogMappingOptions options_from(const SlamHybridArgs& a) {
  LogMappingOptions o;
  if (!a.config.empty()) {
    HybridConfig base;
    base.filter = o.filter;
    const HybridConfig c = load_hybrid_log_config(a.config, base);
    o.filter = c.filter;
    o.landmarks = c.scan_landmarks;
    // Missed detections count inside the range the landmarks are extracted from.
    o.filter.sensor.max_range = o.landmarks.max_range;
  }
  if (a.particles >= 1) o.filter.fastslam.particles = a.particles;
  if (a.seed >= 0) o.filter.fastslam.seed = static_cast<std::uint64_t>(a.seed);
  return o;
}

// A corrected log beside the raw one: GMapping's (fr101.carmen.log -> fr101.carmen.gfs.log),
// else the Radish one named by the log's stem before the first '-'
// (csail-oldcarmen.log -> csail.corrected.log).
std::string reference_log_for(const std::string& log_path) {
  std::string p = log_path;
  if (p.size() > 3 && p.substr(p.size() - 3) == ".gz") p.resize(p.size() - 3);
  if (p.size() < 4 || p.substr(p.size() - 4) != ".log") return "";
  const std::string gfs = p.substr(0, p.size() - 4) + ".gfs.log";
  if (std::filesystem::exists(gfs)) return gfs;
  const std::filesystem::path path(p);
  const std::string stem = path.filename().string();
  const std::string corrected = (path.parent_path() / (stem.substr(0, stem.find('-')) + ".corrected.log")).string();
  return stem.find('-') != std::string::npos && std::filesystem::exists(corrected) ? corrected : "";
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The reference on the raw log's logger clock: a .gfs.log shares the clock; a Radish
// .corrected.log does not (6-digit stamps), so its scans are paired by their ranges.
std::vector<slam::StampedPose> reference_poses(const std::string& reference_path, const slam::LaserLog& log) {
  const slam::LaserLog ref_log = slam::read_carmen_log(reference_path);
  if (ends_with(reference_path, ".corrected.log")) {
    const slam::ScanMatchedReference matched = slam::reference_by_matching_scans(ref_log, log);
    spdlog::info("{}: {} of {} scans paired with the log by their ranges", reference_path, matched.poses.size(),
                 ref_log.scans.size());
    return matched.poses;
  }
  std::vector<slam::StampedPose> reference;
  for (const auto& s : ref_log.scans) reference.push_back({s.timestamp, s.odometry});
  return reference;
}

// Scores the trajectory on the logger clock against the reference's consecutive poses
// (`lookahead eval --reference-log` does the same from the files for a .gfs.log).
nlohmann::json score(const std::vector<slam::StampedPose>& logger_time, const slam::LaserLog& log,
                     const std::string& reference_path) {
  nlohmann::json j;
  if (reference_path.empty()) return j;
  const std::vector<slam::StampedPose> reference = reference_poses(reference_path, log);
  constexpr double kTolerance = 0.051;  // the .gfs.log prints 6 significant digits
  const slam::RelativeError e =
      slam::relative_error(slam::relations_from_reference(reference), logger_time, kTolerance);
  const slam::AbsoluteError ate = slam::absolute_trajectory_error(reference, logger_time, kTolerance);
  j = {{"reference", reference_path}, {"trans_mean_m", e.trans_mean}, {"trans_std_m", e.trans_std},
       {"rot_mean_deg", e.rot_mean},  {"rot_std_deg", e.rot_std},     {"relations_used", e.used},
       {"ate_rmse_m", ate.rmse},      {"ate_matched", ate.matched}};
  spdlog::info("vs {}: relative error {:.3f} +- {:.3f} m, {:.2f} +- {:.2f} deg ({} relations); ATE {:.3f} m",
               reference_path, e.trans_mean, e.trans_std, e.rot_mean, e.rot_std, e.used, ate.rmse);
  return j;
}

slam::ProbabilityMap occupancy_along(const slam::LaserLog& log, const std::vector<slam::Pose2>& path) {
  slam::OccupancyGrid grid;
  slam::InsertOptions insert;
  insert.max_usable_range = 20.0;
  for (std::size_t i = 0; i < path.size(); ++i) slam::insert_scan(grid, path[i], log.scans[i], insert);
  return slam::to_probability_map(grid);
}

void write_landmarks(const std::string& path, const std::vector<MapFeature>& features) {
  std::ofstream f(path);
  f << "# x y cov_xx cov_xy cov_yy  [m, m^2], global frame (the first odometry pose)\n";
  for (const auto& m : features) {
    f << m.mean.x() << " " << m.mean.y() << " " << m.covariance(0, 0) << " " << m.covariance(0, 1) << " "
      << m.covariance(1, 1) << "\n";
  }
}

}  // namespace

int run_slam_hybrid(const slam::LaserLog& log, const SlamHybridArgs& a) {
  const LogMappingOptions options = options_from(a);
  spdlog::info("HybridSLAM: {} scans, {} particles, fusion every {} s", log.scans.size(),
               options.filter.fastslam.particles, options.filter.fusion.period);
  ProgressBar bar("slam --method hybrid", log.scans.size());
  const auto start = std::chrono::steady_clock::now();
  const LogMappingResult r = map_log(log, options, [&](std::size_t done, std::size_t) { bar.update(done); });
  bar.finish();
  const double wall = seconds_since(start);

  std::filesystem::create_directories(a.out);
  std::vector<slam::StampedPose> stamped, logger_time;
  std::vector<slam::Pose2> odometry;
  for (std::size_t i = 0; i < r.trajectory.size(); ++i) {
    stamped.push_back({log.scans[i].timestamp, r.trajectory[i]});
    logger_time.push_back({log.scans[i].logger_timestamp, r.trajectory[i]});
    odometry.push_back(log.scans.front().odometry.compose(log.scans.front().odometry.between(log.scans[i].odometry)));
  }
  slam::write_trajectory(a.out + "/trajectory.txt", stamped);
  slam::write_tum_trajectory(a.out + "/trajectory.tum", stamped);  // for evo
  slam::write_trajectory(a.out + "/trajectory_logger_time.txt", logger_time);
  write_landmarks(a.out + "/landmarks.txt", r.features);
  const slam::ProbabilityMap map = occupancy_along(log, r.trajectory);
  slam::write_map(map, a.out, "map");
  slam::write_map_picture(
      a.out + "/map.png", map,
      {{odometry, {230, 140, 20}, "odometry", 1}, {r.trajectory, {30, 30, 200}, "HybridSLAM estimate", 2}},
      std::filesystem::path(log.path).filename().string() + " - HybridSLAM landmarks over the grid of its path",
      feature_layers(r.features, "landmarks (corners, line ends)", {200, 30, 30}));
  const double duration = log.scans.back().timestamp - log.scans.front().timestamp;
  nlohmann::json j;
  j["method"] = "hybrid";
  j["log"] = log.path;
  j["scans"] = log.scans.size();
  j["landmark_observations"] = r.observations;
  j["landmarks"] = r.features.size();
  j["fusions"] = r.fusions;
  j["wall_time_s"] = wall;
  j["x_real_time"] = duration / wall;
  j["peak_memory_mb"] = peak_memory_mb();
  j["error_vs_reference"] = score(logger_time, log, reference_log_for(log.path));
  write_run_json(a.out, j, 1, dump_hybrid_config({options.filter, {}, {}, options.landmarks}));
  spdlog::info("done in {:.1f} s ({:.1f}x real time): {} landmarks from {} observations, {} fusions; wrote {}/map.png",
               wall, duration / wall, r.features.size(), r.observations, r.fusions, a.out);
  return 0;
}

}  // namespace lookahead::app
