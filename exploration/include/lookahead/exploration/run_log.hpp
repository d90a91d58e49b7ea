// SPDX-License-Identifier: MIT
// A simulated run recorded as a log `lookahead slam` replays: a CARMEN log (CarmenWriter)
// or a ROS1 bag (BagRunLog), chosen by the file's extension.
#pragma once

#include <memory>
#include <string>

#include "lookahead/exploration/laser_simulator.hpp"
#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

class RunLog {
 public:
  virtual ~RunLog() = default;
  /// tv [m/s], rv [rad/s]: the commanded velocities; t [s].
  virtual void odometry(const slam::Pose2& odom, double tv, double rv, double t) = 0;
  virtual void scan(const slam::LaserScan& scan) = 0;
  virtual void true_pose(const slam::Pose2& truth, const slam::Pose2& odom, double t) = 0;
  /// Flushes and closes; throws slam::ParseError if any write failed.
  virtual void close() = 0;
};

/// A .bag path gets a ROS1 bag, any other a CARMEN log.
std::unique_ptr<RunLog> open_run_log(const std::string& path, const LaserOptions& laser);

}  // namespace lookahead::exploration
