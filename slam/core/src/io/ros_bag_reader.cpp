// SPDX-License-Identifier: MIT
// ROS1 bags through rosbag_storage and the message packages' generated (de)serialisers.
// Conventions: REP 103 (x forward, y left, yaw counter-clockwise), REP 105 (odom -> base
// frame for odometry, base -> laser for the mounting). sensor_msgs/LaserScan: beam i is at
// angle_min + i * angle_increment; readings outside [range_min, range_max] or not finite
// are no-returns.
#include <fmt/format.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>

#include "bag_frames.hpp"
#include "bag_message.hpp"
#include "bag_reindex.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/odometry_check.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

constexpr const char* kScanType = "sensor_msgs/LaserScan";
constexpr const char* kOdomType = "nav_msgs/Odometry";

struct Topics {
  std::vector<MessageCount> all;
  std::vector<std::string> of_type(const std::string& type) const {
    std::vector<std::string> out;
    for (const auto& m : all) {
      if (m.type == type) out.push_back(m.topic);
    }
    return out;
  }
  const MessageCount* find(const std::string& topic) const {
    for (const auto& m : all) {
      if (m.topic == topic) return &m;
    }
    return nullptr;
  }
};

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "none" : s;
}

Topics list_topics(rosbag::Bag& bag) {
  Topics t;
  rosbag::View everything(bag);
  for (const rosbag::ConnectionInfo* c : everything.getConnections()) {
    if (t.find(c->topic)) continue;  // several publishers of one topic
    rosbag::View one(bag, rosbag::TopicQuery(c->topic));
    t.all.push_back({c->topic, c->datatype, one.size()});
  }
  return t;
}

std::string choose_scan_topic(const std::string& path, const Topics& t, const BagReadOptions& o) {
  const auto scans = t.of_type(kScanType);
  if (!o.scan_topic.empty()) {
    const MessageCount* m = t.find(o.scan_topic);
    if (!m || m->type != kScanType) {
      throw ParseError(path, 0, "scan topic", o.scan_topic,
                       "no sensor_msgs/LaserScan topic of that name (LaserScan topics: " + joined(scans) + ")");
    }
    return o.scan_topic;
  }
  if (scans.empty()) {
    std::vector<std::string> all;
    for (const auto& m : t.all) all.push_back(m.topic + " [" + m.type + "]");
    throw ParseError(path, 0, "scan topic", "",
                     "no sensor_msgs/LaserScan topic in the bag (topics: " + joined(all) + ")");
  }
  if (scans.size() > 1) {
    throw ParseError(path, 0, "scan topic", joined(scans),
                     "several sensor_msgs/LaserScan topics: choose one with --scan-topic");
  }
  return scans.front();
}

// "" means /tf; otherwise an Odometry topic.
std::string choose_odom_topic(const std::string& path, const Topics& t, const BagReadOptions& o) {
  if (o.odom_topic == "/tf") return "";
  const auto odoms = t.of_type(kOdomType);
  if (!o.odom_topic.empty()) {
    const MessageCount* m = t.find(o.odom_topic);
    if (!m || m->type != kOdomType) {
      throw ParseError(path, 0, "odometry topic", o.odom_topic,
                       "no nav_msgs/Odometry topic of that name (Odometry topics: " + joined(odoms) + ")");
    }
    return o.odom_topic;
  }
  if (odoms.size() == 1) return odoms.front();
  if (std::find(odoms.begin(), odoms.end(), "/odom") != odoms.end()) return "/odom";
  return "";
}

bool covered(const std::vector<TimedPose>& odom, double t, double gap) {
  if (odom.empty() || t < odom.front().t - gap || t > odom.back().t + gap) return false;
  auto hi = std::lower_bound(odom.begin(), odom.end(), t, [](const TimedPose& a, double v) { return a.t < v; });
  if (hi == odom.begin() || hi == odom.end()) return true;  // within `gap` of an end
  return hi->t - (hi - 1)->t <= gap || hi->t == t;
}

LaserScan to_scan(const sensor_msgs::LaserScan& m, double t, const LogReadOptions& o) {
  LaserScan scan;
  scan.timestamp = t;
  scan.logger_timestamp = t;
  const std::size_t n = m.ranges.size();
  scan.max_range = std::min<double>(m.range_max, o.no_return_range);
  scan.angle_min = m.angle_min;
  scan.angle_increment = m.angle_increment;
  scan.ranges.resize(n);
  constexpr float kNoReturn = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const float r = m.ranges[i];
    // Readings above range_max stay as written (is_return() rejects them): only values the
    // message calls invalid (NaN, inf, below range_min) become +inf.
    scan.ranges[i] = std::isfinite(r) && r >= m.range_min ? r : kNoReturn;
  }
  if (m.angle_increment < 0.0f && n > 0) {
    // A clockwise scanner: storing its beams reversed keeps them counter-clockwise from
    // angle_min, as every consumer of LaserScan assumes.
    std::reverse(scan.ranges.begin(), scan.ranges.end());
    scan.angle_min = m.angle_min + m.angle_increment * static_cast<double>(n - 1);
    scan.angle_increment = -static_cast<double>(m.angle_increment);
  }
  return scan;
}

struct ScanReadContext {
  const std::string& path;
  const std::string& topic;
  const LogReadOptions& options;
  const std::vector<TimedPose>& odometry;
  const std::string& odometry_name;
  Pose2 offset;
};

void read_scans(rosbag::Bag& bag, const ScanReadContext& c, LaserLog& log) {
  rosbag::View view(bag, rosbag::TopicQuery(c.topic));
  std::size_t index = 0;
  for (const rosbag::MessageInstance& mi : view) {
    ++index;
    const auto m = read_scan_message(mi);
    if (!m) continue;
    const double t = m->header.stamp.isZero() ? mi.getTime().toSec() : m->header.stamp.toSec();
    if (!covered(c.odometry, t, c.options.bag.max_odometry_gap)) {
      if (log.scans.empty()) {
        ++log.scans_without_odometry;  // the laser started before the odometry: skip
        continue;
      }
      log.scans_without_odometry += view.size() - index + 1;
      log.stopped_early = fmt::format(
          "{}: no odometry from {} around t = {:.6f} s (scan {} of {} on {}); the {} scans before it are kept", c.path,
          c.odometry_name, t, index, view.size(), c.topic, log.scans.size());
      return;
    }
    LaserScan scan = to_scan(*m, t, c.options);
    scan.odometry = interpolate(c.odometry, t);
    scan.laser_offset = c.offset;
    scan.source_line = index;
    log.scans.push_back(std::move(scan));
  }
}

// Opens `path`; a bag without an index (the recording was interrupted, or the file was cut)
// is opened through a copy `rosbag reindex` rebuilds, kept alive in `copy`.
void open_bag(const std::string& path, rosbag::Bag& bag, std::unique_ptr<ReindexedBag>& copy) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ParseError(path, 0, "", "", "no such file (or not a regular file)");
  }
  try {
    bag.open(path, rosbag::bagmode::Read);
    return;
  } catch (const std::exception&) {
    // Unindexed (BagUnindexedException) or cut inside the index: both are what reindex mends.
    bag.close();  // a failed open leaves the file open
  }
  copy = std::make_unique<ReindexedBag>(path);
  try {
    bag.open(copy->path(), rosbag::bagmode::Read);
  } catch (const std::exception& e) {
    throw ParseError(path, 0, "bag", "", std::string("cannot open even after `rosbag reindex`: ") + e.what());
  }
}

std::string salvage_note(const std::string& path, const LaserLog& log) {
  const double end = log.scans.empty() ? 0.0 : log.scans.back().timestamp;
  return fmt::format(
      "{}: the bag has no index (recording interrupted or file truncated); read through a copy "
      "`rosbag reindex` rebuilt: the {} scans up to t = {:.3f} s are kept, the messages of the last, "
      "partial chunk are lost",
      path, log.scans.size(), end);
}

}  // namespace

LaserLog read_ros_bag(const std::string& path, const LogReadOptions& options) {
  LaserLog log;
  log.path = path;
  rosbag::Bag bag;
  std::unique_ptr<ReindexedBag> reindexed;
  open_bag(path, bag, reindexed);
  try {
    const Topics topics = list_topics(bag);
    if (reindexed && topics.all.empty()) {
      throw ParseError(path, 0, "index", "",
                       "the bag has no index (recording interrupted or file truncated, or not a bag) and "
                       "`rosbag reindex` found no complete chunk of messages in it");
    }
    log.messages = topics.all;
    log.scan_source = choose_scan_topic(path, topics, options.bag);
    const std::string odom_topic = choose_odom_topic(path, topics, options.bag);
    BagFrames frames = read_frames(bag, path, odom_topic, options.bag);
    log.odometry_source = frames.odometry_name;
    const std::string laser_frame =
        options.bag.laser_frame.empty() ? first_scan_frame(bag, log.scan_source) : options.bag.laser_frame;
    const Pose2 offset = laser_mounting(bag, path, frames.base_frame, laser_frame);
    read_scans(bag, {path, log.scan_source, options, frames.odometry, frames.odometry_name, offset}, log);
  } catch (const ParseError&) {
    throw;
  } catch (const std::exception& e) {
    // A chunk that does not decompress or a message that does not deserialise: the index
    // was fine, the data behind it is not.
    if (log.scans.empty()) throw ParseError(path, 0, "bag", "", std::string("cannot read: ") + e.what());
    log.stopped_early = fmt::format("{}: reading stopped after {} scans: {}", path, log.scans.size(), e.what());
  }
  if (reindexed) {
    const std::string note = salvage_note(path, log);
    log.stopped_early = log.stopped_early.empty() ? note : note + "; " + log.stopped_early;
  }
  log.lines_read = 0;
  for (const auto& m : log.messages) log.lines_read += m.count;
  check_odometry(log, options);
  return log;
}

}  // namespace lookahead::slam
