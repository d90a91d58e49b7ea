// SPDX-License-Identifier: MIT
// ROS bags written from a real CARMEN log (fr101) with rosbag's writer map to the same
// trajectory as the log itself, through /tf and through /odom; `lookahead slam` on a bag
// writes a TUM trajectory that `lookahead eval` reads back.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
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
