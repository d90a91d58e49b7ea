// SPDX-License-Identifier: MIT
// ROS bags written from a real CARMEN log (fr101) with rosbag's writer map to the same
// trajectory as the log itself, through /tf and through /odom; `lookahead slam` on a bag
// writes a TUM trajectory that `lookahead eval` reads back.
// Cross-check against MRPT's own ROS conversion: the bag converted into an MRPT rawlog by
// MRPT's ros1bridge (LaserScan -> CObservation2DRangeScan, Odometry -> CObservationOdometry,
// the mounting from /tf_static) maps to the bag's trajectory. Debian's rosbag2rawlog
// (mrpt-apps 2.5.8) converts images, point clouds and IMU readings but no LaserScan, so its
// library is called directly, as rosbag2rawlog would.
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
#include <sys/wait.h>
#include <tf2_msgs/TFMessage.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/ros_bag_writer.hpp"
#include "lookahead/slam/io/tum_trajectory.hpp"
#include "lookahead/slam/rbpf/rbpf.hpp"

namespace lookahead::slam {
namespace {

namespace fs = std::filesystem;
const std::string kFr101 = std::string(LOOKAHEAD_SHARED_DIR) + "/data/fr101/fr101.carmen.log";
constexpr std::size_t kScans = 250;

// The first kScans scans of fr101. CARMEN lines carry the laser pose rounded to 1e-6, so
// the offset recovered per line jitters by about 1e-6 m; a bag states the mounting once,
// so the log keeps its first scan's offset for all (the filter sees the same data twice).
const LaserLog& fr101_prefix() {
  static const LaserLog log = [] {
    LaserLog l = read_carmen_log(kFr101);
    l.scans.resize(kScans);
    for (LaserScan& s : l.scans) s.laser_offset = l.scans.front().laser_offset;
    return l;
  }();
  return log;
}

fs::path temp(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lookahead-bag-test-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

void write_bag(const LaserLog& log, const std::string& path, BagWriteOptions options) {
  RosBagWriter writer(path, std::move(options));
  for (const LaserScan& s : log.scans) {
    writer.odometry(s.timestamp, s.odometry);
    writer.scan(s);
  }
  writer.close();
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

void expect_same_trajectory(const std::vector<Pose2>& a, const std::vector<Pose2>& b) {
  ASSERT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(
        {worst, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y), std::abs(normalize_angle(a[i].theta - b[i].theta))});
  }
  EXPECT_LT(worst, 1e-6) << "largest pose difference";
}

#define SKIP_WITHOUT_FR101() \
  if (!fs::exists(kFr101)) GTEST_SKIP() << "no shared data: " << kFr101

TEST(BagFromCarmen, MapsToTheSameTrajectoryViaTfAndViaOdom) {
  SKIP_WITHOUT_FR101();
  const LaserLog& carmen = fr101_prefix();
  const std::vector<Pose2> expected = map_log(carmen);
  for (const bool via_tf : {true, false}) {
    const std::string path = temp(via_tf ? "tf.bag" : "odom.bag").string();
    BagWriteOptions w;
    w.odometry_on_tf = via_tf;
    w.odom_topic = via_tf ? "" : "/odom";
    write_bag(carmen, path, w);
    const LaserLog bag = read_ros_bag(path);
    ASSERT_EQ(bag.scans.size(), kScans);
    EXPECT_EQ(bag.odometry_source, via_tf ? "/tf odom -> base_link" : "/odom");
    EXPECT_NEAR(bag.scans[0].laser_offset.x, carmen.scans[0].laser_offset.x, 1e-12);
    expect_same_trajectory(map_log(bag), expected);
  }
}

// fr101_prefix() without each scan's first beam. fr101's 180 beams run from -90 to +89 deg; a
// CObservation2DRangeScan has no angle_min (its beams span -aperture/2 .. +aperture/2 about
// the sensor's x axis), so ros1bridge reads such a scan back turned by half a beam. From
// -89 deg the scan is symmetric and both representations state the same beams.
LaserLog symmetric_fr101_prefix() {
  LaserLog log = fr101_prefix();
  for (LaserScan& s : log.scans) {
    s.ranges.erase(s.ranges.begin());
    s.angle_min += s.angle_increment;
  }
  return log;
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

TEST(BagMrptCrossCheck, MrptsConversionOfABagMapsToTheSameTrajectory) {
  SKIP_WITHOUT_FR101();
  const std::string bag = temp("fr101.bag").string();
  const std::string rawlog = temp("fr101.rawlog").string();
  BagWriteOptions w;
  w.odometry_on_tf = false;  // odometry on /odom only: what ros1bridge converts
  write_bag(symmetric_fr101_prefix(), bag, w);
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
}

struct Shell {
  int code;
  std::string output;
};

Shell shell(const std::string& cmd) {
  const fs::path out = temp("shell.txt");
  const int status = std::system((cmd + " > " + out.string() + " 2>&1").c_str());
  std::stringstream text;
  text << std::ifstream(out).rdbuf();
  return {WEXITSTATUS(status), text.str()};
}

TEST(BagFromCarmen, SlamOnABagWritesATumTrajectoryThatEvalReadsBack) {
  SKIP_WITHOUT_FR101();
  const std::string bag = temp("cli.bag").string();
  write_bag(fr101_prefix(), bag, {});
  const fs::path out = temp("slam-out");
  const std::string bin = LOOKAHEAD_BINARY;
  const Shell slam =
      shell(bin + " slam " + bag + " --particles 5 --seed 2 --threads 1 --max-scans 120 --out " + out.string());
  ASSERT_EQ(slam.code, 0) << slam.output;
  ASSERT_TRUE(fs::exists(out / "trajectory.tum"));
  ASSERT_TRUE(fs::exists(out / "run.json"));
  EXPECT_EQ(read_any_trajectory((out / "trajectory.tum").string()).size(), 120u);
  const Shell eval = shell(bin + " eval --trajectory " + (out / "trajectory.tum").string() + " --reference " +
                           (out / "trajectory.txt").string() + " --json");
  ASSERT_EQ(eval.code, 0) << eval.output;
  EXPECT_NE(eval.output.find("nearest estimate stamp"), std::string::npos) << eval.output;
  EXPECT_NE(eval.output.find("120 of 120 reference poses matched"), std::string::npos) << eval.output;
  EXPECT_NE(eval.output.find("\"ate_rmse_m\":0.0"), std::string::npos) << eval.output;
  const Shell missing = shell(bin + " slam " + bag + " --scan-topic /front_scan --out " + out.string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.output.find("/front_scan"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace lookahead::slam
