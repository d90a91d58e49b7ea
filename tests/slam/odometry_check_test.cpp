// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/odometry_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lookahead/slam/rbpf/rbpf.hpp"
#include "lookahead/slam/segslam/seg_slam.hpp"

namespace lookahead::slam {
namespace {

// A corridor seen by a 181-beam laser: walls 2 m to either side, the robot driving along x.
LaserScan corridor_scan(double t, double x) {
  LaserScan s;
  s.timestamp = s.logger_timestamp = t;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 180;
  s.max_range = 30;
  for (int i = 0; i <= 180; ++i) {
    const double a = s.angle_min + i * s.angle_increment;
    const double r = std::abs(std::sin(a)) > 0.1 ? 2.0 / std::abs(std::sin(a)) : 30.0;
    s.ranges.push_back(static_cast<float>(std::min(r, 29.0)));
  }
  s.odometry = {x, 0.0, 0.0};
  s.source_line = static_cast<std::size_t>(t);
  return s;
}

LaserLog corridor_log(int scans) {
  LaserLog log;
  log.path = "corridor.log";
  for (int i = 0; i < scans; ++i) log.scans.push_back(corridor_scan(i + 1.0, 0.3 * i));
  return log;
}

TEST(OdometryCheck, NonFinitePoseAndTimeAreSkippedWithTheirLine) {
  LaserLog log = corridor_log(5);
  log.scans[1].odometry.y = std::numeric_limits<double>::quiet_NaN();
  log.scans[3].timestamp = std::numeric_limits<double>::infinity();
  check_odometry(log, {});
  EXPECT_EQ(log.scans.size(), 3u);
  EXPECT_EQ(log.non_finite.count, 2u);
  EXPECT_NE(log.non_finite.first.find("corridor.log:2:"), std::string::npos) << log.non_finite.first;
}

TEST(OdometryCheck, TimeGoingBackwardsIsCountedAndKeptInLogOrder) {
  LaserLog log = corridor_log(5);
  log.scans[2].timestamp = 0.5;
  check_odometry(log, {});
  ASSERT_EQ(log.scans.size(), 5u);
  EXPECT_EQ(log.time_reversals.count, 1u);
  EXPECT_EQ(log.scans[2].timestamp, 0.5);
  EXPECT_NE(log.time_reversals.first.find("corridor.log:3:"), std::string::npos) << log.time_reversals.first;
}

// The jumps of a wrapped-around odometer: every filter maps on, within the map's limits.
LaserLog jumping_log(double jump) {
  LaserLog log = corridor_log(30);
  for (std::size_t i = 15; i < log.scans.size(); ++i) log.scans[i].odometry.x += jump;
  check_odometry(log, {});
  return log;
}

TEST(OdometryCheck, RbpfMapsThrough100KilometreJump) {
  const LaserLog log = jumping_log(1e5);
  EXPECT_EQ(log.odometry_jumps.count, 1u);
  RbpfOptions o;
  o.particles = 4;
  o.threads = 2;
  Rbpf filter(o);
  for (const LaserScan& s : log.scans) filter.add_scan(s);
  EXPECT_LT(std::abs(filter.current_pose().x), 20.0);
}

TEST(OdometryCheck, SegSlamMapsThrough1KilometreJump) {
  const LaserLog log = jumping_log(1e3);
  EXPECT_EQ(log.odometry_jumps.count, 1u);
  segslam::SegSlamOptions o;
  RbpfOptions r;
  r.particles = 4;
  r.threads = 2;
  segslam::SegSlam filter(r, o);
  for (const LaserScan& s : log.scans) filter.add_scan(s);
  EXPECT_EQ(filter.scans().size(), log.scans.size());
}

}  // namespace
}  // namespace lookahead::slam
