// SPDX-License-Identifier: MIT
// Writes a simulated run as a CARMEN log that slam::read_carmen_log (and so `lookahead slam`)
// replays. Line formats as in shared/data/SOURCES.md section 2.1:
//   PARAM name value ipc host logger
//   ODOM x y theta tv rv accel ipc host logger
//   FLASER n r1..rn laser_x laser_y laser_theta odom_x odom_y odom_theta ipc host logger
//   TRUEPOS true_x true_y true_theta odom_x odom_y odom_theta ipc host logger
// (TRUEPOS is CARMEN's simulator message for the ground truth; the reader skips it.)
// The header PARAMs tell the reader the field of view, the no-return range and the laser
// offset, so the replay needs no options.
#pragma once

#include <cstdio>
#include <string>

#include "lookahead/exploration/laser_simulator.hpp"
#include "lookahead/exploration/run_log.hpp"
#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::exploration {

class CarmenWriter : public RunLog {
 public:
  /// Creates `path` and writes the PARAM header for `laser`; throws slam::ParseError naming
  /// the file when it cannot be opened.
  CarmenWriter(const std::string& path, const LaserOptions& laser, std::string host = "lookahead-sim");
  ~CarmenWriter() override;
  CarmenWriter(const CarmenWriter&) = delete;
  CarmenWriter& operator=(const CarmenWriter&) = delete;

  /// tv [m/s], rv [rad/s]: the commanded velocities; t [s] is written as both timestamps.
  void odometry(const slam::Pose2& odom, double tv, double rv, double t) override;
  /// FLASER from scan.ranges, scan.odometry, scan.laser_offset and scan.timestamp.
  void scan(const slam::LaserScan& scan) override;
  void true_pose(const slam::Pose2& truth, const slam::Pose2& odom, double t) override;
  /// Flushes and closes; throws slam::ParseError if any write failed. The destructor closes
  /// without throwing.
  void close() override;

 private:
  void tail(double t);
  std::string path_;
  std::string host_;
  std::FILE* f_ = nullptr;
};

}  // namespace lookahead::exploration
