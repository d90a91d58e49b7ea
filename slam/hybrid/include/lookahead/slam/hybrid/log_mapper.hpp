// SPDX-License-Identifier: MIT
// HybridSLAM on a real laser log: odometry increments with the RBPF's noise model as the
// control, corners and line ends of each scan as range-bearing observations, the
// FastSLAM front-end fused into the EKF global map every fusion.period seconds.
#pragma once

#include <functional>
#include <vector>

#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/scan_landmarks.hpp"
#include "lookahead/slam/hybrid/submap_filter.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"

namespace lookahead::slam::hybrid {

struct LogMappingOptions {
  HybridOptions filter = laser_defaults();
  MotionModelOptions motion;  ///< odometry noise (the RBPF's srr/srt/str/stt model)
  ScanLandmarkOptions landmarks;

  /// HybridSLAM sec. 5 values where they carry over; for a laser's corners and line ends
  /// (seen about half the time, with spurious ones from clutter and people) alpha = 0.5,
  /// beta = 0.1, and fewer particles because a local map stays small.
  static HybridOptions laser_defaults();
};

struct LogMappingResult {
  std::vector<Pose2> trajectory;     ///< per scan, global estimate
  std::vector<MapFeature> features;  ///< final global feature map
  std::size_t observations = 0;      ///< landmarks extracted over the log
  int fusions = 0;
};

using LogProgress = std::function<void(std::size_t done, std::size_t total)>;

LogMappingResult map_log(const LaserLog& log, const LogMappingOptions& options, const LogProgress& progress = {});

}  // namespace lookahead::slam::hybrid
