// SPDX-License-Identifier: MIT
// A simulated run as a ROS1 bag (slam::RosBagWriter): /scan, /odom and odom -> base_link on
// /tf, base_link -> laser on /tf_static, the true pose on /base_pose_ground_truth.
#pragma once

#include <string>

#include "lookahead/exploration/run_log.hpp"
#include "lookahead/slam/io/ros_bag_writer.hpp"

namespace lookahead::exploration {

class BagRunLog : public RunLog {
 public:
  /// Throws slam::ParseError naming the file when it cannot be created.
  BagRunLog(const std::string& path, const LaserOptions& laser);
  void odometry(const slam::Pose2& odom, double tv, double rv, double t) override;
  void scan(const slam::LaserScan& scan) override;
  void true_pose(const slam::Pose2& truth, const slam::Pose2& odom, double t) override;
  void close() override;

 private:
  slam::RosBagWriter writer_;
};

}  // namespace lookahead::exploration
