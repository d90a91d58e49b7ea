// SPDX-License-Identifier: MIT
// A laser log as the filter consumes it: scans in time order, each with its odometry pose.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "lookahead/slam/sensor/laser_scan.hpp"

namespace lookahead::slam {

/// Where a ROS bag keeps its scans, odometry and laser mounting (REP 105 frame names).
struct BagReadOptions {
  /// sensor_msgs/LaserScan topic; empty: the bag's only LaserScan topic.
  std::string scan_topic;
  /// nav_msgs/Odometry topic, or "/tf" for the odom -> base transform; empty: the only
  /// Odometry topic (or /odom among several), else /tf.
  std::string odom_topic;
  std::string odom_frame = "odom";
  /// Robot frame; empty: the Odometry messages' child_frame_id, or the one child of
  /// odom_frame on /tf.
  std::string base_frame;
  /// Laser frame; empty: the scans' header.frame_id. Its pose in base_frame comes from
  /// /tf_static or /tf.
  std::string laser_frame;
  /// Scans whose stamp lies more than this outside the odometry, or inside a longer gap
  /// between two odometry readings, have no odometry [s].
  double max_odometry_gap = 1.0;
};

struct LogReadOptions {
  /// Count and skip malformed lines instead of stopping at the first one.
  bool skip_bad_lines = false;
  /// Readings at or above this are no-returns even where the log claims a larger max range
  /// (CARMEN logs write 81.83/81.91 for "no echo") [m].
  double no_return_range = 80.0;
  /// Odometry steps between consecutive scans longer than this are jumps: the motion model
  /// is reset there (odometry_check.hpp) [m], (0, 1000]. A robot does not cover 10 m
  /// between two scans; a reset or wrapped-around odometer does.
  double max_odometry_step = 10.0;
  BagReadOptions bag;
};

/// Scans a reader dropped or changed, with the first as "file:line: what" for the log.
struct LogEvent {
  std::size_t count = 0;
  std::string first;
};

/// One message kind of the input (CARMEN: the line's first word; bag: topic and type).
struct MessageCount {
  std::string topic;
  std::string type;
  std::size_t count = 0;
};

struct LaserLog {
  std::string path;
  std::vector<LaserScan> scans;
  std::size_t lines_read = 0;
  std::size_t bad_lines = 0;           ///< skipped with --skip-bad-lines
  std::string first_bad_line_message;  ///< what was wrong with the first skipped line
  std::vector<MessageCount> messages;  ///< every message kind in the input, counted
  std::string scan_source;             ///< message kind or topic the scans came from
  std::string odometry_source;         ///< where the scans' odometry came from
  /// Scans the input carries again in another message kind (same ranges), not used twice.
  std::size_t duplicate_scans = 0;
  /// Scans left out because no odometry covers their time; what was read before is kept.
  std::size_t scans_without_odometry = 0;
  /// Why reading stopped before the end of the input (names topic, frame or time); empty
  /// when it read to the end.
  std::string stopped_early;
  LogEvent non_finite;      ///< scans with a non-finite odometry pose or time, skipped
  LogEvent time_reversals;  ///< scans stamped before the previous one, kept in log order
  LogEvent odometry_jumps;  ///< steps over max_odometry_step, where the motion model was reset
};

/// Reads a CARMEN log (.log/.clf, or the same gzip-compressed with .gz).
LaserLog read_carmen_log(const std::string& path, const LogReadOptions& options = {});
/// Reads an MRPT .rawlog through MRPT's own deserialisation.
LaserLog read_mrpt_rawlog(const std::string& path, const LogReadOptions& options = {});
/// Reads a ROS1 bag through rosbag's own storage library: sensor_msgs/LaserScan, odometry
/// from nav_msgs/Odometry or /tf, the laser mounting from /tf_static or /tf.
LaserLog read_ros_bag(const std::string& path, const LogReadOptions& options = {});
/// Chooses the reader by the file's extension (.rawlog -> MRPT, .bag -> ROS bag, anything
/// else -> CARMEN).
LaserLog read_laser_log(const std::string& path, const LogReadOptions& options = {});

}  // namespace lookahead::slam
