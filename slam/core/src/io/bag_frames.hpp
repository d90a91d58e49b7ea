// SPDX-License-Identifier: MIT
// What a ROS bag says about where the robot and its laser were: odometry (nav_msgs/Odometry
// or the odom -> base transform on /tf) and the laser mounting (base -> laser on /tf_static
// or /tf). Frame names follow REP 105; a leading '/' (tf1 style) is ignored.
#pragma once

#include <rosbag/bag.h>

#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::slam {

struct TimedPose {
  double t = 0.0;
  Pose2 pose;
};

struct BagFrames {
  std::vector<TimedPose> odometry;  ///< sorted by stamp
  std::string odometry_name;        ///< "/odom" or "/tf odom -> base_link"
  std::string base_frame;
};

/// Odometry from `odom_topic`, or from /tf when it is empty; errors name the frames seen.
BagFrames read_frames(rosbag::Bag& bag, const std::string& path, const std::string& odom_topic,
                      const BagReadOptions& options);
/// header.frame_id of the first message on the scan topic.
std::string first_scan_frame(rosbag::Bag& bag, const std::string& scan_topic);
/// The laser's pose in the base frame (identity when they are the same frame).
Pose2 laser_mounting(rosbag::Bag& bag, const std::string& path, const std::string& base_frame,
                     const std::string& laser_frame);
/// Odometry at `t`, interpolated between the readings around it (held at the ends).
Pose2 interpolate(const std::vector<TimedPose>& odometry, double t);

}  // namespace lookahead::slam
