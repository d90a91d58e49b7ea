// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/log_mapper.hpp"

#include "lookahead/slam/hybrid/fastslam.hpp"

namespace lookahead::slam::hybrid {

HybridOptions LogMappingOptions::laser_defaults() {
  HybridOptions o;
  o.existence.alpha = 0.5;
  o.existence.beta = 0.1;
  o.fastslam.particles = 100;
  o.sensor.max_range = 15.0;  // = ScanLandmarkOptions::max_range: missed detections count inside it
  return o;
}

LogMappingResult map_log(const LaserLog& log, const LogMappingOptions& options, const LogProgress& progress) {
  LogMappingResult result;
  if (log.scans.empty()) return result;
  const Pose2 start = log.scans.front().odometry;
  SubmapFilter filter(std::make_unique<FastSlam>(options.filter, options.filter.fastslam.seed), options.filter, start,
                      true);
  const OdometryMotionModel motion(options.motion);
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScan& scan = log.scans[i];
    MotionStep step;
    if (i > 0) {
      step.delta = log.scans[i - 1].odometry.between(scan.odometry);
      motion.sigmas(step.delta, step.sigma.x(), step.sigma.y(), step.sigma.z());
      step.dt = std::max(scan.timestamp - log.scans[i - 1].timestamp, 0.0);
    } else {
      step.dt = 0.0;
    }
    std::vector<RangeBearing> z;
    for (const ScanLandmark& l : extract_scan_landmarks(scan, options.landmarks)) z.push_back(to_observation(l));
    result.observations += z.size();
    filter.step(step, z);
    result.trajectory.push_back(filter.vehicle().mean);
    if (progress) progress(i + 1, log.scans.size());
  }
  filter.finish();
  result.features = filter.feature_map();
  result.fusions = filter.fusions();
  return result;
}

}  // namespace lookahead::slam::hybrid
