// SPDX-License-Identifier: MIT
// The readers on the real logs of ../shared/data (counts from shared/data/SOURCES.md).
#include <gtest/gtest.h>

#include <cmath>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::slam {
namespace {

std::string data(const std::string& rel) { return std::string(LOOKAHEAD_SHARED_DIR) + "/data/" + rel; }

TEST(RealLogs, Fr101RawLogHasEveryScanWithOdometry) {
  const LaserLog log = read_carmen_log(data("fr101/fr101.carmen.log"));
  ASSERT_EQ(log.scans.size(), 4758u);
  const LaserScan& s = log.scans.front();
  EXPECT_EQ(s.ranges.size(), 360u);
  EXPECT_NEAR(s.angle_increment, M_PI / 360, 1e-12);
  EXPECT_NEAR(s.laser_offset.x, -0.04, 0.002);  // robot_frontlaser_offset -0.04
  EXPECT_DOUBLE_EQ(s.timestamp, 407.318438);
  EXPECT_DOUBLE_EQ(s.logger_timestamp, 156.315436);
  for (std::size_t i = 1; i < log.scans.size(); ++i) ASSERT_GE(log.scans[i].timestamp, log.scans[i - 1].timestamp);
}

TEST(RealLogs, GzipAndPlainCopiesReadTheSame) {
  const LaserLog plain = read_carmen_log(data("fr101/fr101.carmen.log"));
  const LaserLog gz = read_carmen_log(data("fr101/fr101.carmen.log.gz"));
  ASSERT_EQ(plain.scans.size(), gz.scans.size());
  EXPECT_EQ(plain.scans.back().ranges, gz.scans.back().ranges);
  EXPECT_EQ(plain.scans.back().odometry.x, gz.scans.back().odometry.x);
}

TEST(RealLogs, CsailTripledScansAreReadOnce) {
  const LaserLog old_carmen = read_carmen_log(data("mit-csail/csail-oldcarmen.log"));
  const LaserLog new_carmen = read_carmen_log(data("mit-csail/csail-newcarmen.log"));
  ASSERT_EQ(old_carmen.scans.size(), 1988u);  // FLASER, not FLASER + ROBOTLASER1 + RAWLASER1
  ASSERT_EQ(new_carmen.scans.size(), 1988u);  // ROBOTLASER1
  EXPECT_EQ(old_carmen.scans[0].ranges.size(), 361u);
  EXPECT_NEAR(old_carmen.scans[0].angle_increment, M_PI / 360, 1e-6);  // PARAM fov 3.14159
  EXPECT_NEAR(new_carmen.scans[0].angle_increment, 0.008727, 1e-9);
  EXPECT_FALSE(old_carmen.scans[0].is_return(0) && old_carmen.scans[0].ranges[0] >= 80.0f);
  EXPECT_NEAR(old_carmen.scans[100].timestamp, new_carmen.scans[100].timestamp, 1e-6);
}

TEST(RealLogs, GmappingOutputsAndFlirtLogsParse) {
  EXPECT_EQ(read_carmen_log(data("fr101/fr101.carmen.gfs.log")).scans.size(), 292u);
  EXPECT_EQ(read_carmen_log(data("intel/intel.gfs.log")).scans.size(), 910u);
  EXPECT_EQ(read_carmen_log(data("fr079/fr079-complete.gfs.log.gz")).scans.size(), 4791u);
  EXPECT_EQ(read_carmen_log(data("aces/aces-corrected.log")).scans.size(), 440u);
  EXPECT_EQ(read_carmen_log(data("derived-flirtlib/intel-lab.log")).scans.size(), 2672u);
  EXPECT_EQ(read_carmen_log(data("derived-flirtlib/fr079.log")).scans.size(), 1464u);
}

}  // namespace
}  // namespace lookahead::slam
