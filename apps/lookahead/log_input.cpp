// SPDX-License-Identifier: MIT
#include "log_input.hpp"

#include <spdlog/spdlog.h>

#include "lookahead/slam/io/log_check.hpp"

namespace lookahead::app {

void add_bag_options(CLI::App& app, slam::BagReadOptions& bag) {
  app.add_option("--scan-topic", bag.scan_topic, "bag: sensor_msgs/LaserScan topic (default: the only one)");
  app.add_option("--odom-topic", bag.odom_topic,
                 "bag: nav_msgs/Odometry topic, or /tf (default: the only Odometry topic, /odom, else /tf)");
  app.add_option("--odom-frame", bag.odom_frame, "bag: odometry frame on /tf")->capture_default_str();
  app.add_option("--base-frame", bag.base_frame,
                 "bag: robot frame (default: the Odometry child_frame_id, or the child of the odom frame)");
  app.add_option("--laser-frame", bag.laser_frame, "bag: laser frame (default: the scans' frame_id)");
}

slam::LaserLog load_laser_log(const std::string& path, const slam::LogReadOptions& read, std::size_t max_scans) {
  spdlog::info("reading {}", path);
  slam::LaserLog log = slam::read_laser_log(path, read);
  const slam::LogCheck check = slam::check_log(log);
  for (const slam::Finding& f : check.findings) {
    if (f.severity != slam::Severity::kNote) spdlog::warn("{}: {}", f.code, f.message);
  }
  if (log.scans.empty()) throw std::runtime_error(path + ": no laser scans in the log");
  if (max_scans > 0 && log.scans.size() > max_scans) log.scans.resize(max_scans);
  return log;
}

}  // namespace lookahead::app
