// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/ros_bag_writer.hpp"

#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

geometry_msgs::Quaternion yaw_quaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

geometry_msgs::TransformStamped transform(const ros::Time& t, const std::string& parent, const std::string& child,
                                          const Pose2& p) {
  geometry_msgs::TransformStamped tr;
  tr.header.stamp = t;
  tr.header.frame_id = parent;
  tr.child_frame_id = child;
  tr.transform.translation.x = p.x;
  tr.transform.translation.y = p.y;
  tr.transform.rotation = yaw_quaternion(p.theta);
  return tr;
}

nav_msgs::Odometry odometry_message(const ros::Time& t, const std::string& frame, const std::string& child,
                                    const Pose2& p) {
  nav_msgs::Odometry m;
  m.header.stamp = t;
  m.header.frame_id = frame;
  m.child_frame_id = child;
  m.pose.pose.position.x = p.x;
  m.pose.pose.position.y = p.y;
  m.pose.pose.orientation = yaw_quaternion(p.theta);
  return m;
}

}  // namespace

struct RosBagWriter::Impl {
  std::string path;
  BagWriteOptions options;
  rosbag::Bag bag;
  bool mounting_written = false;
  std::uint32_t seq = 0;
};

RosBagWriter::RosBagWriter(const std::string& path, BagWriteOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  impl_->options = std::move(options);
  try {
    impl_->bag.open(path, rosbag::bagmode::Write);
  } catch (const std::exception& e) {
    throw ParseError(path, 0, "", "", std::string("cannot open for writing: ") + e.what());
  }
}

RosBagWriter::~RosBagWriter() {
  try {
    impl_->bag.close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; close() reports
  }
}

void RosBagWriter::odometry(double t, const Pose2& pose) {
  const BagWriteOptions& o = impl_->options;
  const ros::Time stamp(t);
  if (!o.odom_topic.empty()) {
    impl_->bag.write(o.odom_topic, std::max(stamp, ros::TIME_MIN),
                     odometry_message(stamp, o.odom_frame, o.base_frame, pose));
  }
  if (o.odometry_on_tf) {
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(transform(stamp, o.odom_frame, o.base_frame, pose));
    impl_->bag.write("/tf", std::max(stamp, ros::TIME_MIN), tf);
  }
}

void RosBagWriter::scan(const LaserScan& s) {
  const BagWriteOptions& o = impl_->options;
  const ros::Time stamp(s.timestamp);
  if (!impl_->mounting_written) {
    tf2_msgs::TFMessage tf;
    tf.transforms.push_back(transform(stamp, o.base_frame, o.laser_frame, s.laser_offset));
    impl_->bag.write("/tf_static", std::max(stamp, ros::TIME_MIN), tf);
    impl_->mounting_written = true;
  }
  sensor_msgs::LaserScan m;
  m.header.stamp = stamp;
  m.header.frame_id = o.laser_frame;
  m.header.seq = impl_->seq++;
  m.angle_min = static_cast<float>(s.angle_min);
  m.angle_increment = static_cast<float>(s.angle_increment);
  m.angle_max = static_cast<float>(s.angle_min + s.angle_increment * static_cast<double>(s.ranges.size() - 1));
  m.range_min = 0.0f;
  m.range_max = static_cast<float>(s.max_range);
  m.ranges = s.ranges;
  impl_->bag.write(o.scan_topic, std::max(stamp, ros::TIME_MIN), m);
}

void RosBagWriter::ground_truth(double t, const Pose2& pose) {
  if (impl_->options.ground_truth_topic.empty()) return;
  const ros::Time stamp(t);
  impl_->bag.write(impl_->options.ground_truth_topic, std::max(stamp, ros::TIME_MIN),
                   odometry_message(stamp, "map", impl_->options.base_frame, pose));
}

void RosBagWriter::close() {
  try {
    impl_->bag.close();
  } catch (const std::exception& e) {
    throw ParseError(impl_->path, 0, "", "", std::string("write failed: ") + e.what());
  }
}

}  // namespace lookahead::slam
