// SPDX-License-Identifier: MIT
// A simulated run written as CARMEN and read back by the project's own reader.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lookahead/exploration/carmen_writer.hpp"
#include "lookahead/exploration/generated_worlds.hpp"
#include "lookahead/exploration/odometry_model.hpp"
#include "lookahead/exploration/robot.hpp"
#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::exploration {
namespace {

TEST(CarmenWriter, RoundTripsThroughTheSlamReader) {
  const GeneratedWorld g = make_pslam_maze();
  LaserOptions lo;
  lo.offset = {0.1, 0.0, 0.0};
  LaserSimulator laser(g.world, lo);
  Robot robot(g.world, g.start);
  OdometryModel odom(g.start);
  slam::test::TempPath log(".log");
  std::vector<slam::LaserScan> written;
  {
    CarmenWriter writer(log.str(), lo);
    for (int k = 0; k < 40; ++k) {
      const double t = k * lo.period();
      const slam::Pose2 before = robot.pose();
      robot.step(0.2, 0.1, lo.period());
      odom.update(before.between(robot.pose()));
      writer.odometry(odom.pose(), 0.2, 0.1, t);
      writer.true_pose(robot.pose(), odom.pose(), t);
      slam::LaserScan s = laser.scan(robot.pose(), t);
      s.odometry = odom.pose();
      writer.scan(s);
      written.push_back(s);
    }
    writer.close();
  }
  const slam::LaserLog read = slam::read_carmen_log(log.str());
  ASSERT_EQ(read.scans.size(), written.size());
  for (std::size_t k = 0; k < written.size(); ++k) {
    const slam::LaserScan& a = written[k];
    const slam::LaserScan& b = read.scans[k];
    ASSERT_EQ(a.ranges.size(), b.ranges.size());
    for (std::size_t i = 0; i < a.ranges.size(); ++i) {
      EXPECT_NEAR(a.ranges[i], b.ranges[i], 6e-5);
      EXPECT_EQ(a.is_return(i), b.is_return(i));
    }
    EXPECT_NEAR(b.odometry.x, a.odometry.x, 1e-6);
    EXPECT_NEAR(b.odometry.theta, a.odometry.theta, 1e-6);
    EXPECT_NEAR(b.laser_offset.x, 0.1, 1e-5);
    EXPECT_NEAR(b.angle_min, a.angle_min, 1e-6);
    EXPECT_NEAR(b.angle_increment, a.angle_increment, 1e-6);
    EXPECT_DOUBLE_EQ(b.max_range, lo.max_range);
    EXPECT_NEAR(b.timestamp, a.timestamp, 1e-6);
  }
}

TEST(CarmenWriter, UnwritablePathIsAParseError) {
  EXPECT_THROW({ CarmenWriter w("/nonexistent-dir/x.log", LaserOptions{}); }, slam::ParseError);
}

}  // namespace
}  // namespace lookahead::exploration
