// SPDX-License-Identifier: MIT
// Writes laser scans and odometry as a ROS1 bag with rosbag's own writer, in the layout a
// ROS robot records (REP 105): sensor_msgs/LaserScan on the scan topic, odometry as
// nav_msgs/Odometry and/or the odom -> base transform on /tf, the laser mounting as
// base -> laser on /tf_static. read_ros_bag (and so `lookahead slam`) replays it.
#pragma once

#include <memory>
#include <string>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam {

struct BagWriteOptions {
  std::string scan_topic = "/scan";
  std::string odom_topic = "/odom";  ///< nav_msgs/Odometry; empty: none
  bool odometry_on_tf = true;        ///< also odom -> base on /tf
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::string laser_frame = "laser";
  /// Topic of the true pose (nav_msgs/Odometry in frame "map"); Stage's name by default.
  std::string ground_truth_topic = "/base_pose_ground_truth";
};

class RosBagWriter {
 public:
  /// Creates `path`; throws ParseError naming the file when it cannot.
  RosBagWriter(const std::string& path, BagWriteOptions options = {});
  ~RosBagWriter();
  RosBagWriter(const RosBagWriter&) = delete;
  RosBagWriter& operator=(const RosBagWriter&) = delete;

  /// Odometry pose at time t [s].
  void odometry(double t, const Pose2& pose);
  /// The scan at scan.timestamp; the first one also writes its laser_offset to /tf_static.
  void scan(const LaserScan& scan);
  void ground_truth(double t, const Pose2& pose);
  /// Writes the index and closes; throws ParseError if writing failed.
  void close();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lookahead::slam
