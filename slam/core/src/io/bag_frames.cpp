// SPDX-License-Identifier: MIT
#include "bag_frames.hpp"

#include <fmt/format.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "bag_message.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

std::string bare(const std::string& frame) { return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame; }

// Planar pose of a 3D transform: REP 103 yaw of the quaternion.
Pose2 planar(const geometry_msgs::Vector3& p, const geometry_msgs::Quaternion& q) {
  const double yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  return {p.x, p.y, normalize_angle(yaw)};
}
Pose2 planar(const geometry_msgs::Point& p, const geometry_msgs::Quaternion& q) {
  geometry_msgs::Vector3 v;
  v.x = p.x;
  v.y = p.y;
  return planar(v, q);
}

void sort_by_stamp(std::vector<TimedPose>& odometry) {
  std::stable_sort(odometry.begin(), odometry.end(), [](const TimedPose& a, const TimedPose& b) { return a.t < b.t; });
}

BagFrames odometry_from_topic(rosbag::Bag& bag, const std::string& topic, const BagReadOptions& o) {
  BagFrames f;
  f.odometry_name = topic;
  f.base_frame = bare(o.base_frame);
  rosbag::View view(bag, rosbag::TopicQuery(topic));
  for (const rosbag::MessageInstance& mi : view) {
    // No variable-length array in an Odometry message: its strings ROS checks before it
    // allocates, so the generated deserialiser is safe on corrupt bytes.
    const auto m = mi.instantiate<nav_msgs::Odometry>();
    if (!m) continue;
    if (f.base_frame.empty()) f.base_frame = bare(m->child_frame_id);
    const double t = m->header.stamp.isZero() ? mi.getTime().toSec() : m->header.stamp.toSec();
    f.odometry.push_back({t, planar(m->pose.pose.position, m->pose.pose.orientation)});
  }
  if (f.base_frame.empty()) f.base_frame = "base_link";
  return f;
}

// Every parent -> child pair on the tf topics, for error messages.
std::set<std::string> frame_pairs(rosbag::Bag& bag) {
  std::set<std::string> pairs;
  rosbag::View view(bag, rosbag::TopicQuery(std::vector<std::string>{"/tf", "/tf_static"}));
  for (const rosbag::MessageInstance& mi : view) {
    const auto m = read_tf_message(mi);
    if (!m) continue;
    for (const auto& tr : m->transforms) pairs.insert(bare(tr.header.frame_id) + " -> " + bare(tr.child_frame_id));
  }
  return pairs;
}

std::string listed(const std::set<std::string>& pairs) {
  std::string s;
  for (const auto& p : pairs) s += (s.empty() ? "" : ", ") + p;
  return s.empty() ? "no transforms at all" : s;
}

// The one child of `parent` on /tf (the robot frame under odom); empty if none or several.
std::string only_child(rosbag::Bag& bag, const std::string& parent) {
  std::set<std::string> children;
  rosbag::View view(bag, rosbag::TopicQuery("/tf"));
  for (const rosbag::MessageInstance& mi : view) {
    const auto m = read_tf_message(mi);
    if (!m) continue;
    for (const auto& tr : m->transforms) {
      if (bare(tr.header.frame_id) == parent) children.insert(bare(tr.child_frame_id));
    }
  }
  return children.size() == 1 ? *children.begin() : "";
}

BagFrames odometry_from_tf(rosbag::Bag& bag, const std::string& path, const BagReadOptions& o) {
  BagFrames f;
  const std::string odom = bare(o.odom_frame);
  f.base_frame = o.base_frame.empty() ? only_child(bag, odom) : bare(o.base_frame);
  f.odometry_name = "/tf " + odom + " -> " + (f.base_frame.empty() ? "?" : f.base_frame);
  rosbag::View view(bag, rosbag::TopicQuery("/tf"));
  for (const rosbag::MessageInstance& mi : view) {
    const auto m = read_tf_message(mi);
    if (!m) continue;
    for (const auto& tr : m->transforms) {
      if (bare(tr.header.frame_id) != odom || bare(tr.child_frame_id) != f.base_frame) continue;
      f.odometry.push_back({tr.header.stamp.toSec(), planar(tr.transform.translation, tr.transform.rotation)});
    }
  }
  if (f.odometry.empty()) {
    throw ParseError(path, 0, "odometry frames", odom + " -> " + (f.base_frame.empty() ? "(base)" : f.base_frame),
                     "no nav_msgs/Odometry topic, and /tf has no such transform (seen: " + listed(frame_pairs(bag)) +
                         "); set --odom-frame/--base-frame or --odom-topic");
  }
  return f;
}

}  // namespace

BagFrames read_frames(rosbag::Bag& bag, const std::string& path, const std::string& odom_topic,
                      const BagReadOptions& options) {
  BagFrames f =
      odom_topic.empty() ? odometry_from_tf(bag, path, options) : odometry_from_topic(bag, odom_topic, options);
  if (f.odometry.empty()) throw ParseError(path, 0, "odometry topic", odom_topic, "has no nav_msgs/Odometry messages");
  sort_by_stamp(f.odometry);
  return f;
}

std::string first_scan_frame(rosbag::Bag& bag, const std::string& scan_topic) {
  rosbag::View view(bag, rosbag::TopicQuery(scan_topic));
  for (const rosbag::MessageInstance& mi : view) {
    const auto m = read_scan_message(mi);
    if (m) return bare(m->header.frame_id);
  }
  return "";
}

Pose2 laser_mounting(rosbag::Bag& bag, const std::string& path, const std::string& base_frame,
                     const std::string& laser_frame) {
  const std::string laser = bare(laser_frame);
  if (laser.empty() || laser == base_frame) return {};
  // /tf_static first: a mounting is static; a /tf copy is taken only when there is none.
  for (const char* topic : {"/tf_static", "/tf"}) {
    rosbag::View view(bag, rosbag::TopicQuery(topic));
    for (const rosbag::MessageInstance& mi : view) {
      const auto m = read_tf_message(mi);
      if (!m) continue;
      for (const auto& tr : m->transforms) {
        if (bare(tr.header.frame_id) == base_frame && bare(tr.child_frame_id) == laser) {
          return planar(tr.transform.translation, tr.transform.rotation);
        }
      }
    }
  }
  throw ParseError(path, 0, "laser frames", base_frame + " -> " + laser,
                   "no such transform on /tf_static or /tf (seen: " + listed(frame_pairs(bag)) +
                       "); set --base-frame/--laser-frame (--laser-frame " + base_frame +
                       " for a laser at the robot's origin)");
}

Pose2 interpolate(const std::vector<TimedPose>& odom, double t) {
  if (odom.empty()) return {};
  auto hi = std::lower_bound(odom.begin(), odom.end(), t, [](const TimedPose& a, double v) { return a.t < v; });
  if (hi == odom.begin()) return odom.front().pose;
  if (hi == odom.end()) return odom.back().pose;
  if (hi->t == t) return hi->pose;
  const auto lo = hi - 1;
  const double a = (t - lo->t) / (hi->t - lo->t);
  const Pose2 d = lo->pose.between(hi->pose);
  return lo->pose.compose({a * d.x, a * d.y, a * d.theta});
}

}  // namespace lookahead::slam
