// SPDX-License-Identifier: MIT
// Cross-check of the bag path against MRPT's own ROS conversion: a bag written from a real
// CARMEN log (fr101) is converted into an MRPT rawlog by MRPT's ros1bridge (LaserScan ->
// CObservation2DRangeScan, Odometry -> CObservationOdometry, the mounting from /tf_static),
// and mapping that rawlog gives the trajectory that mapping the bag gives. Debian's
// rosbag2rawlog (mrpt-apps 2.5.8) converts images, point clouds and IMU readings but no
// LaserScan, so its library is called directly, as rosbag2rawlog would.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/ros1bridge/laser_scan.h>
#include <mrpt/ros1bridge/pose.h>
#include <mrpt/ros1bridge/time.h>
#include <mrpt/serialization/CArchive.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_msgs/TFMessage.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/ros_bag_writer.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"

namespace lookahead::slam {
namespace {

namespace fs = std::filesystem;
const std::string kFr101 = std::string(LOOKAHEAD_SHARED_DIR) + "/data/fr101/fr101.carmen.log";
constexpr std::size_t kScans = 250;

fs::path temp(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lookahead-mrpt-cross-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// The first kScans scans of fr101 with one mounting for all (a bag states it once), without
// their first beam. fr101's 180 beams run from -90 to +89 deg; a CObservation2DRangeScan has
// no angle_min (its beams span -aperture/2 .. +aperture/2 about the sensor's x axis), so
// ros1bridge reads such a scan back turned by half a beam. From -89 deg the scan is symmetric
// and both representations state the same beams.
LaserLog fr101_prefix() {
  LaserLog log = read_carmen_log(kFr101);
  log.scans.resize(kScans);
  for (LaserScan& s : log.scans) {
    s.laser_offset = log.scans.front().laser_offset;
    s.ranges.erase(s.ranges.begin());
    s.angle_min += s.angle_increment;
  }
  return log;
}

void write_bag(const LaserLog& log, const std::string& path) {
  BagWriteOptions o;
  o.odometry_on_tf = false;  // odometry on /odom only: what ros1bridge converts
  RosBagWriter writer(path, o);
  for (const LaserScan& s : log.scans) {
    writer.odometry(s.timestamp, s.odometry);
    writer.scan(s);
  }
  writer.close();
}

// The bag as MRPT's ros1bridge converts it: a flat rawlog of observations in bag order.
void convert_with_mrpt(const std::string& bag_path, const std::string& rawlog_path) {
  rosbag::Bag bag(bag_path, rosbag::bagmode::Read);
  mrpt::poses::CPose3D mounting;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery("/tf_static"))) {
    for (const auto& t : m.instantiate<tf2_msgs::TFMessage>()->transforms) {
      geometry_msgs::Pose p;
      p.position.x = t.transform.translation.x, p.position.y = t.transform.translation.y;
      p.position.z = t.transform.translation.z, p.orientation = t.transform.rotation;
      if (t.child_frame_id == "laser") mounting = mrpt::ros1bridge::fromROS(p);
    }
  }
  // Records in time order; at one stamp the odometry first, so each scan follows the
  // odometry reading of its own time (the bag's index leaves equal stamps in either order).
  struct Record {
    double stamp;
    int rank;
    mrpt::serialization::CSerializable::Ptr object;
  };
  std::vector<Record> records;
  for (const rosbag::MessageInstance& m :
       rosbag::View(bag, rosbag::TopicQuery(std::vector<std::string>{"/scan", "/odom"}))) {
    if (const auto scan = m.instantiate<sensor_msgs::LaserScan>()) {
      auto obs = mrpt::obs::CObservation2DRangeScan::Create();
      EXPECT_TRUE(mrpt::ros1bridge::fromROS(*scan, mounting, *obs));
      records.push_back({scan->header.stamp.toSec(), 1, obs});
    } else if (const auto odom = m.instantiate<nav_msgs::Odometry>()) {
      auto obs = mrpt::obs::CObservationOdometry::Create();
      obs->timestamp = mrpt::ros1bridge::fromROS(odom->header.stamp);
      obs->odometry = mrpt::poses::CPose2D(mrpt::ros1bridge::fromROS(odom->pose.pose));
      records.push_back({odom->header.stamp.toSec(), 0, obs});
    }
  }
  std::stable_sort(records.begin(), records.end(), [](const Record& a, const Record& b) {
    return std::tie(a.stamp, a.rank) < std::tie(b.stamp, b.rank);
  });
  mrpt::io::CFileGZOutputStream out(rawlog_path);
  auto archive = mrpt::serialization::archiveFrom(out);
  for (const Record& r : records) archive << r.object;
}

std::vector<Pose2> map_log(const LaserLog& log) {
  RbpfOptions o;
  o.particles = 8;
  o.seed = 5;
  o.threads = 1;
  Rbpf filter(o);
  for (const LaserScan& s : log.scans) filter.add_scan(s);
  return filter.best_trajectory();
}

TEST(BagMrptCrossCheck, MrptsConversionOfABagMapsToTheSameTrajectory) {
  if (!fs::exists(kFr101)) GTEST_SKIP() << "no shared data: " << kFr101;
  const std::string bag = temp("fr101.bag").string();
  const std::string rawlog = temp("fr101.rawlog").string();
  write_bag(fr101_prefix(), bag);
  convert_with_mrpt(bag, rawlog);
  const LaserLog from_bag = read_ros_bag(bag);
  const LaserLog from_rawlog = read_mrpt_rawlog(rawlog);
  ASSERT_EQ(from_rawlog.scans.size(), from_bag.scans.size());
  // The inputs agree first: the same beams, ranges, mounting and odometry per scan.
  for (std::size_t i = 0; i < from_bag.scans.size(); ++i) {
    const LaserScan &a = from_bag.scans[i], &b = from_rawlog.scans[i];
    ASSERT_EQ(a.ranges.size(), b.ranges.size()) << "scan " << i;
    EXPECT_NEAR(a.timestamp, b.timestamp, 1e-6) << "scan " << i;
    EXPECT_NEAR(a.angle_min, b.angle_min, 1e-6) << "scan " << i;
    EXPECT_NEAR(a.angle_increment, b.angle_increment, 1e-7) << "scan " << i;
    EXPECT_NEAR(a.laser_offset.x, b.laser_offset.x, 1e-9) << "scan " << i;
    // ros1bridge marks readings at range_max invalid, which the rawlog reader reads as
    // infinite: a no-return both ways.
    for (std::size_t k = 0; k < a.ranges.size(); ++k) {
      ASSERT_EQ(a.is_return(k), b.is_return(k)) << "scan " << i << " beam " << k;
      if (a.is_return(k)) ASSERT_EQ(a.ranges[k], b.ranges[k]) << "scan " << i << " beam " << k;
    }
    // The rawlog reader starts odometry at the origin: compare the motion since the first scan.
    const Pose2 da = from_bag.scans[0].odometry.inverse().compose(a.odometry);
    const Pose2 db = from_rawlog.scans[0].odometry.inverse().compose(b.odometry);
    EXPECT_NEAR(da.x, db.x, 1e-9) << "scan " << i;
    EXPECT_NEAR(da.y, db.y, 1e-9) << "scan " << i;
    EXPECT_NEAR(normalize_angle(da.theta - db.theta), 0.0, 1e-9) << "scan " << i;
  }
  // Mapped, the two give one trajectory up to the frame each starts in.
  const std::vector<Pose2> ta = map_log(from_bag), tb = map_log(from_rawlog);
  ASSERT_EQ(ta.size(), tb.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < ta.size(); ++i) {
    const Pose2 ra = ta.front().inverse().compose(ta[i]), rb = tb.front().inverse().compose(tb[i]);
    worst = std::max({worst, std::hypot(ra.x - rb.x, ra.y - rb.y), std::abs(normalize_angle(ra.theta - rb.theta))});
  }
  EXPECT_LT(worst, 1e-6) << "largest pose difference";
  fs::remove_all(temp("").parent_path());
}

}  // namespace
}  // namespace lookahead::slam
