// SPDX-License-Identifier: MIT
// read_ros_bag() on small bags written here with rosbag's own writer: scan geometry as the
// message states it, odometry interpolated to the scan stamps, the laser mounting from
// /tf_static, and each bad bag's error naming the topic, frame or time.
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/io/ros_bag_writer.hpp"
#include "temp_file.hpp"

namespace lookahead::slam {
namespace {

using test::TempPath;

sensor_msgs::LaserScan laser_message(double t, const std::string& frame = "laser") {
  sensor_msgs::LaserScan m;
  m.header.stamp = ros::Time(t);
  m.header.frame_id = frame;
  m.angle_min = -1.0f;
  m.angle_increment = 0.5f;
  m.angle_max = 1.0f;
  m.range_min = 0.1f;
  m.range_max = 30.0f;
  m.ranges = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f};
  return m;
}

geometry_msgs::TransformStamped tf(double t, const std::string& parent, const std::string& child, double x, double y,
                                   double yaw) {
  geometry_msgs::TransformStamped tr;
  tr.header.stamp = ros::Time(t);
  tr.header.frame_id = parent;
  tr.child_frame_id = child;
  tr.transform.translation.x = x;
  tr.transform.translation.y = y;
  tr.transform.rotation.z = std::sin(yaw / 2);
  tr.transform.rotation.w = std::cos(yaw / 2);
  return tr;
}

void write_tf(rosbag::Bag& bag, const std::string& topic, const geometry_msgs::TransformStamped& tr) {
  tf2_msgs::TFMessage m;
  m.transforms.push_back(tr);
  bag.write(topic, std::max(tr.header.stamp, ros::TIME_MIN), m);  // a bag holds no record at 0
}

// odom -> base_link on /tf at 0, 1, ..., n-1 s moving 1 m/s along x; laser 0.2 m ahead.
void write_robot(rosbag::Bag& bag, int n, const std::string& odom = "odom") {
  write_tf(bag, "/tf_static", tf(0.0, "base_link", "laser", 0.2, 0.0, 0.0));
  for (int i = 0; i < n; ++i) write_tf(bag, "/tf", tf(i, odom, "base_link", i, 0.0, 0.1 * i));
}

TEST(RosBagReader, InterpolatesTfOdometryToScanStampsAndReadsTheMounting) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 4);
    bag.write("/scan", ros::Time(1.5), laser_message(1.5));
    bag.write("/scan", ros::Time(2.0), laser_message(2.0));
  }
  const LaserLog log = read_ros_bag(path.str());
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.scan_source, "/scan");
  EXPECT_EQ(log.odometry_source, "/tf odom -> base_link");
  EXPECT_NEAR(log.scans[0].odometry.x, 1.5, 1e-9);
  EXPECT_NEAR(log.scans[0].odometry.theta, 0.15, 1e-9);
  EXPECT_NEAR(log.scans[1].odometry.x, 2.0, 1e-12);  // on a reading: exactly it
  EXPECT_NEAR(log.scans[0].laser_offset.x, 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(log.scans[0].timestamp, 1.5);
}

TEST(RosBagReader, ScanGeometryAsTheMessageStatesIt) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 3);
    sensor_msgs::LaserScan m = laser_message(1.0);
    // Clockwise scanner, NaN and inf no-returns, a reading below range_min, one above max.
    m.angle_min = 1.0f;
    m.angle_increment = -0.5f;
    m.ranges = {1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 0.05f, 40.0f};
    bag.write("/scan", ros::Time(1.0), m);
  }
  const LaserScan s = read_ros_bag(path.str()).scans.at(0);
  EXPECT_NEAR(s.angle_min, -1.0, 1e-7);
  EXPECT_NEAR(s.angle_increment, 0.5, 1e-7);
  ASSERT_EQ(s.ranges.size(), 5u);
  EXPECT_FLOAT_EQ(s.ranges[4], 1.0f);  // reversed: the first beam of a CW scan is the last CCW
  EXPECT_FALSE(s.is_return(0));        // 40 m >= range_max 30 m
  EXPECT_FALSE(s.is_return(1));        // below range_min
  EXPECT_FALSE(s.is_return(2));        // inf
  EXPECT_FALSE(s.is_return(3));        // NaN
  EXPECT_TRUE(s.is_return(4));
  EXPECT_DOUBLE_EQ(s.max_range, 30.0);
}

TEST(RosBagReader, OdometryTopicWinsAndItsChildFrameNamesTheBase) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_tf(bag, "/tf_static", tf(0.0, "base_footprint", "laser", -0.1, 0.05, M_PI));
    for (int i = 0; i < 3; ++i) {
      nav_msgs::Odometry o;
      o.header.stamp = ros::Time(i);
      o.header.frame_id = "odom";
      o.child_frame_id = "base_footprint";
      o.pose.pose.position.y = 2.0 * i;
      o.pose.pose.orientation.w = 1.0;
      bag.write("/wheel_odom", std::max(o.header.stamp, ros::TIME_MIN), o);
    }
    bag.write("/scan", ros::Time(0.5), laser_message(0.5));
  }
  const LaserLog log = read_ros_bag(path.str());
  EXPECT_EQ(log.odometry_source, "/wheel_odom");
  EXPECT_NEAR(log.scans.at(0).odometry.y, 1.0, 1e-6);  // the first record sits at ros::TIME_MIN, 1 ns after 0
  EXPECT_NEAR(log.scans.at(0).laser_offset.y, 0.05, 1e-12);
  EXPECT_NEAR(std::abs(log.scans.at(0).laser_offset.theta), M_PI, 1e-9);
}

std::string error_of(const std::string& path, const LogReadOptions& options = {}) {
  try {
    read_ros_bag(path, options);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

TEST(RosBagReader, NoScanTopicNamesTheTopicsThereAre) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 2);
  }
  const std::string e = error_of(path.str());
  EXPECT_NE(e.find("no sensor_msgs/LaserScan topic"), std::string::npos) << e;
  EXPECT_NE(e.find("/tf [tf2_msgs/TFMessage]"), std::string::npos) << e;
}

TEST(RosBagReader, TwoScanTopicsNeedAChoice) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 3);
    bag.write("/front/scan", ros::Time(1.0), laser_message(1.0));
    bag.write("/rear/scan", ros::Time(1.0), laser_message(1.0));
  }
  const std::string e = error_of(path.str());
  EXPECT_NE(e.find("/front/scan, /rear/scan"), std::string::npos) << e;
  EXPECT_NE(e.find("--scan-topic"), std::string::npos) << e;
  LogReadOptions chosen;
  chosen.bag.scan_topic = "/rear/scan";
  EXPECT_EQ(read_ros_bag(path.str(), chosen).scans.size(), 1u);
  chosen.bag.scan_topic = "/side/scan";
  EXPECT_NE(error_of(path.str(), chosen).find("/side/scan"), std::string::npos);
}

TEST(RosBagReader, MismatchedFrameNamesAreNamed) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 3, "odom_combined");
    bag.write("/scan", ros::Time(1.0), laser_message(1.0, "hokuyo"));
  }
  const std::string odom = error_of(path.str());
  EXPECT_NE(odom.find("odom -> (base)"), std::string::npos) << odom;
  EXPECT_NE(odom.find("odom_combined -> base_link"), std::string::npos) << odom;
  LogReadOptions o;
  o.bag.odom_frame = "odom_combined";
  const std::string laser = error_of(path.str(), o);
  EXPECT_NE(laser.find("base_link -> hokuyo"), std::string::npos) << laser;
  o.bag.laser_frame = "laser";
  EXPECT_EQ(read_ros_bag(path.str(), o).scans.size(), 1u);
}

TEST(RosBagReader, OdometryEndingEarlyKeepsTheScansBeforeAndNamesTheTime) {
  TempPath path(".bag");
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 3);  // odometry 0..2 s
    for (int i = 0; i < 8; ++i) bag.write("/scan", std::max(ros::Time(0.5 * i), ros::TIME_MIN), laser_message(0.5 * i));
  }
  const LaserLog log = read_ros_bag(path.str());
  EXPECT_EQ(log.scans.size(), 7u);  // 0 .. 3 s: the last within max_odometry_gap (1 s) of 2 s
  EXPECT_EQ(log.scans_without_odometry, 1u);
  EXPECT_NE(log.stopped_early.find("t = 3.500000"), std::string::npos) << log.stopped_early;
  EXPECT_NE(log.stopped_early.find("/tf odom -> base_link"), std::string::npos) << log.stopped_early;
}

// ROS's deserialiser would resize `ranges` to a corrupted length (8 GB here) before reading
// it: the length is checked against the message first, and the scans before it are kept.
TEST(RosBagReader, AScanWithACorruptedArrayLengthStopsTheReadingAndNamesTheArray) {
  TempPath path(".bag");
  constexpr float kMarker = 7.25f;  // the first range of scan 5 only
  {
    rosbag::Bag bag(path.str(), rosbag::bagmode::Write);
    write_robot(bag, 6);
    for (int i = 0; i < 10; ++i) {
      sensor_msgs::LaserScan m = laser_message(0.5 * i);
      if (i == 5) m.ranges[0] = kMarker;
      bag.write("/scan", std::max(ros::Time(0.5 * i), ros::TIME_MIN), m);
    }
  }
  std::ifstream in(path.str(), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::uint32_t five = 5;
  std::string pattern(reinterpret_cast<const char*>(&five), 4);
  pattern.append(reinterpret_cast<const char*>(&kMarker), 4);
  const std::size_t at = bytes.find(pattern);
  ASSERT_NE(at, std::string::npos);
  const std::uint32_t corrupt = 0x7ffffff0u;
  bytes.replace(at, 4, reinterpret_cast<const char*>(&corrupt), 4);
  path.write(bytes);

  const LaserLog log = read_ros_bag(path.str());
  EXPECT_EQ(log.scans.size(), 5u);
  EXPECT_NE(log.stopped_early.find("ranges declares 2147483632 x 4 bytes"), std::string::npos) << log.stopped_early;
  EXPECT_NE(log.stopped_early.find("t = 2.500000 s on /scan"), std::string::npos) << log.stopped_early;
}

// A bag of `scans` scans of 360 beams (about four of rosbag's 768 KB chunks for 2000), cut
// at 2/3 of its size as an interrupted recording would leave it; returns the cut size.
std::uintmax_t write_cut_bag(const std::string& path, int scans) {
  {
    RosBagWriter writer(path);
    LaserScan s;
    s.ranges.assign(360, 2.0f);
    s.angle_increment = 0.01;
    for (int i = 0; i < scans; ++i) {
      s.timestamp = i * 0.1;
      writer.odometry(s.timestamp, {0.01 * i, 0, 0});
      writer.scan(s);
    }
    writer.close();
  }
  const auto cut = std::filesystem::file_size(path) * 2 / 3;
  std::filesystem::resize_file(path, cut);
  return cut;
}

// rosbag writes a bag's index when it closes it: a recording cut short has none. The
// scans of its complete chunks are read through a copy `rosbag reindex` rebuilds.
TEST(RosBagReader, ATruncatedBagKeepsTheScansOfItsCompleteChunks) {
  TempPath path(".bag");
  constexpr int kScans = 2000;
  const auto cut = write_cut_bag(path.str(), kScans);
  const LaserLog log = read_ros_bag(path.str());
  EXPECT_GT(log.scans.size(), kScans / 4u);
  EXPECT_LT(log.scans.size(), kScans * 2u / 3u);
  EXPECT_NE(log.stopped_early.find(path.str()), std::string::npos) << log.stopped_early;
  EXPECT_NE(log.stopped_early.find("rosbag reindex"), std::string::npos) << log.stopped_early;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    ASSERT_NEAR(log.scans[i].timestamp, 0.1 * static_cast<double>(i), 1e-6);  // none lost before the cut
    ASSERT_NEAR(log.scans[i].odometry.x, 0.01 * static_cast<double>(i), 1e-9);
  }
  EXPECT_EQ(std::filesystem::file_size(path.str()), cut);  // the user's file is not touched
}

TEST(RosBagReader, WithoutRosbagReindexATruncatedBagNamesThePackage) {
  TempPath path(".bag");
  write_cut_bag(path.str(), 200);
  const std::string saved = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", "/nonexistent", 1);  // no `rosbag` to be found
  const std::string e = error_of(path.str());
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_NE(e.find(path.str()), std::string::npos) << e;
  EXPECT_NE(e.find("python3-rosbag"), std::string::npos) << e;
}

// The reindexed copy is as large as the bag; /proc is a file system with no room at all.
TEST(RosBagReader, ATruncatedBagIsRefusedUpFrontWhenTheTemporaryFolderHasNoRoomForItsCopy) {
  TempPath path(".bag");
  write_cut_bag(path.str(), 200);
  const std::string saved = std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "";
  ::setenv("TMPDIR", "/proc", 1);
  const std::string e = error_of(path.str());
  saved.empty() ? ::unsetenv("TMPDIR") : ::setenv("TMPDIR", saved.c_str(), 1);
  EXPECT_NE(e.find(path.str()), std::string::npos) << e;
  EXPECT_NE(e.find("/proc has 0.0 MB free"), std::string::npos) << e;
  EXPECT_NE(e.find("TMPDIR"), std::string::npos) << e;
}

TEST(RosBagReader, FilesThatAreNoBagAreParseErrors) {
  test::TempPath garbage(".bag");
  garbage.write("#ROSBAG V2.0\nnot a bag at all");
  const std::string e = error_of(garbage.str());
  EXPECT_NE(e.find(garbage.str()), std::string::npos) << e;
  EXPECT_NE(e.find("rosbag reindex"), std::string::npos) << e;
  EXPECT_THROW(read_ros_bag("/nonexistent/x.bag"), ParseError);
}

TEST(RosBagWriter, RoundTripsThroughTheReaderOnTfAloneAndOnOdometryAlone) {
  for (const bool tf_only : {true, false}) {
    TempPath path(".bag");
    BagWriteOptions o;
    o.odometry_on_tf = tf_only;
    o.odom_topic = tf_only ? "" : "/odom";
    {
      RosBagWriter writer(path.str(), o);
      LaserScan s;
      s.ranges = {1.0f, 2.5f, 81.91f};
      s.angle_min = -M_PI / 2;
      s.angle_increment = M_PI / 2;
      s.laser_offset = {0.1, -0.02, 0.05};
      for (int i = 0; i < 5; ++i) {
        s.timestamp = 100.0 + 0.25 * i;
        s.odometry = {0.3 * i, -0.1 * i, normalize_angle(2.0 * i)};
        writer.odometry(s.timestamp, s.odometry);
        writer.scan(s);
      }
      writer.close();
    }
    const LaserLog log = read_ros_bag(path.str());
    ASSERT_EQ(log.scans.size(), 5u);
    EXPECT_EQ(log.odometry_source, tf_only ? "/tf odom -> base_link" : "/odom");
    for (int i = 0; i < 5; ++i) {
      const LaserScan& s = log.scans[static_cast<std::size_t>(i)];
      EXPECT_NEAR(s.timestamp, 100.0 + 0.25 * i, 1e-8);
      EXPECT_NEAR(s.odometry.x, 0.3 * i, 1e-12);
      EXPECT_NEAR(normalize_angle(s.odometry.theta - 2.0 * i), 0.0, 1e-12);
      EXPECT_NEAR(s.laser_offset.theta, 0.05, 1e-12);
      EXPECT_FLOAT_EQ(s.ranges[2], 81.91f);
      EXPECT_FALSE(s.is_return(2));  // at or above the 80 m no-return range
    }
  }
}

}  // namespace
}  // namespace lookahead::slam
