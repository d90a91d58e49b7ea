// SPDX-License-Identifier: MIT
#include "lookahead/exploration/carmen_writer.hpp"

#include <utility>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {

CarmenWriter::CarmenWriter(const std::string& path, const LaserOptions& laser, std::string host)
    : path_(path), host_(std::move(host)) {
  laser.validate();  // before opening, so a throw cannot leave the file open
  f_ = std::fopen(path.c_str(), "w");
  if (!f_) throw slam::ParseError(path, 0, "", "", "cannot open for writing");
  std::fprintf(f_, "# CARMEN log written by the lookahead simulator\n");
  // The reader takes the FLASER field of view from this PARAM (radians, as CSAIL's log has
  // it), and readings >= robot_front_laser_max as no-returns.
  const double values[] = {laser.fov, laser.max_range, laser.offset.x};
  const char* names[] = {"laser_front_laser_fov", "robot_front_laser_max", "robot_frontlaser_offset"};
  for (int i = 0; i < 3; ++i) {
    std::fprintf(f_, "PARAM %s %.6f", names[i], values[i]);
    tail(0.0);
  }
}

CarmenWriter::~CarmenWriter() {
  if (f_) std::fclose(f_);
}

void CarmenWriter::tail(double t) { std::fprintf(f_, " %.6f %s %.6f\n", t, host_.c_str(), t); }

void CarmenWriter::odometry(const slam::Pose2& odom, double tv, double rv, double t) {
  std::fprintf(f_, "ODOM %.6f %.6f %.6f %.6f %.6f 0.000000", odom.x, odom.y, odom.theta, tv, rv);
  tail(t);
}

void CarmenWriter::scan(const slam::LaserScan& s) {
  std::fprintf(f_, "FLASER %zu", s.ranges.size());
  // 0.1 mm: finer than any noise the simulator adds, so the round trip changes nothing.
  for (const float r : s.ranges) std::fprintf(f_, " %.4f", static_cast<double>(r));
  const slam::Pose2 laser = s.odometry.compose(s.laser_offset);
  std::fprintf(f_, " %.6f %.6f %.6f %.6f %.6f %.6f", laser.x, laser.y, laser.theta, s.odometry.x, s.odometry.y,
               s.odometry.theta);
  tail(s.timestamp);
}

void CarmenWriter::true_pose(const slam::Pose2& truth, const slam::Pose2& odom, double t) {
  std::fprintf(f_, "TRUEPOS %.6f %.6f %.6f %.6f %.6f %.6f", truth.x, truth.y, truth.theta, odom.x, odom.y, odom.theta);
  tail(t);
}

void CarmenWriter::close() {
  if (!f_) return;
  const bool failed = std::ferror(f_) != 0;
  const bool close_failed = std::fclose(f_) != 0;
  f_ = nullptr;
  if (failed || close_failed) throw slam::ParseError(path_, 0, "", "", "write failed");
}

}  // namespace lookahead::exploration
