// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <random>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::slam {
namespace {

std::string ranges(int n, const std::string& value) {
  std::string s;
  for (int i = 0; i < n; ++i) s += value + " ";
  return s;
}

std::string flaser(int n, double t, const std::string& r = "2.0") {
  return "FLASER " + std::to_string(n) + " " + ranges(n, r) + "1.0 2.0 0.0 1.04 2.0 0.0 " + std::to_string(t) +
         " host " + std::to_string(t - 100) + "\n";
}

LaserLog read_text(const std::string& text, const LogReadOptions& o = {}) {
  test::TempPath f(".log");
  f.write(text);
  return read_carmen_log(f.str(), o);
}

TEST(CarmenReader, FlaserBeamGeometryFollowsTheBeamCount) {
  for (const auto& [n, inc, start] : {std::tuple{180, 1.0, -90.0}, std::tuple{181, 1.0, -90.0},
                                      std::tuple{360, 0.5, -90.0}, std::tuple{361, 0.5, -90.0}}) {
    const LaserLog log = read_text(flaser(n, 5.0));
    ASSERT_EQ(log.scans.size(), 1u);
    const LaserScan& s = log.scans[0];
    EXPECT_EQ(s.ranges.size(), static_cast<std::size_t>(n));
    EXPECT_NEAR(s.angle_increment * 180 / M_PI, inc, 1e-9) << n;
    EXPECT_NEAR(s.angle_min * 180 / M_PI, start, 1e-9) << n;
  }
}

TEST(CarmenReader, FlaserFieldOfViewParamIsReadInRadiansOrDegrees) {
  for (const std::string& fov : {"3.14159", "180"}) {
    const LaserScan s = read_text("PARAM laser_front_laser_fov " + fov + " h 0\n" + flaser(181, 5.0)).scans.at(0);
    EXPECT_NEAR(s.angle_increment * 180 / M_PI, 1.0, 1e-4) << fov;
    EXPECT_NEAR(s.angle_min * 180 / M_PI, -90.0, 1e-3) << fov;
  }
  const LaserScan wide = read_text("PARAM laser_front_laser_fov 4.71239 h 0\n" + flaser(271, 5.0)).scans.at(0);
  EXPECT_NEAR(wide.angle_min * 180 / M_PI, -135.0, 1e-3);
}

TEST(CarmenReader, AFieldOfViewBeyondAFullTurnNamesLineAndValue) {
  for (const std::string& fov : {"720", "-1", "0", "wide", "3.1x"}) {
    try {
      read_text(flaser(180, 1.0) + "PARAM laser_front_laser_fov " + fov + " h 0\n" + flaser(180, 2.0));
      FAIL() << "no error for " << fov;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), 2u);
      EXPECT_EQ(e.field(), "laser_front_laser_fov");
      EXPECT_EQ(e.value(), fov);
    }
  }
}

TEST(CarmenReader, FlaserCarriesTimesOdometryAndLaserOffset) {
  const LaserScan s = read_text(flaser(180, 1234.5)).scans.at(0);
  EXPECT_DOUBLE_EQ(s.timestamp, 1234.5);
  EXPECT_DOUBLE_EQ(s.logger_timestamp, 1134.5);
  EXPECT_DOUBLE_EQ(s.odometry.x, 1.04);
  EXPECT_DOUBLE_EQ(s.odometry.theta, 0.0);
  EXPECT_NEAR(s.laser_offset.x, -0.04, 1e-9);  // laser 4 cm behind the robot's origin
  EXPECT_NEAR(s.laser_offset.y, 0.0, 1e-9);
  EXPECT_EQ(s.source_line, 1u);
}

TEST(CarmenReader, MaxRangeNanAndInfAreNoReturns) {
  const std::string line = "FLASER 4 1.5 81.91 nan inf 0 0 0 0 0 0 1.0 h 1.0\n";
  const LaserScan s = read_text(line).scans.at(0);
  EXPECT_TRUE(s.is_return(0));
  EXPECT_FALSE(s.is_return(1));
  EXPECT_FALSE(s.is_return(2));
  EXPECT_FALSE(s.is_return(3));
}

TEST(CarmenReader, RobotLaserUsesItsOwnGeometryAndBothTrailerLengths) {
  const std::string head = "ROBOTLASER1 0 -1.570796 3.141593 0.017453 50.0 0.1 0 180 " + ranges(180, "3.0");
  const std::string with_axis = head + "0 1 2 0.1 1 2 0.1 0 0 0.57 0.37 1000000 55.5 h 5.5\n";
  const std::string without_axis = head + "0 1 2 0.1 1 2 0.1 0 0 0.57 0.37 56.5 h 6.5\n";
  const LaserLog log = read_text(with_axis + without_axis);
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_NEAR(log.scans[0].angle_increment, 0.017453, 1e-9);
  EXPECT_DOUBLE_EQ(log.scans[0].max_range, 50.0);
  EXPECT_DOUBLE_EQ(log.scans[1].timestamp, 56.5);
  EXPECT_DOUBLE_EQ(log.scans[1].odometry.y, 2.0);
}

TEST(CarmenReader, PrefersFlaserWhenALogRepeatsScansInSeveralMessages) {
  const std::string raw = "RAWLASER1 0 -1.570796 3.141593 0.008727 81.92 0.05 0 2 1 1 0 9.0 h 9.0\n";
  const LaserLog log = read_text(raw + flaser(180, 9.0) + raw);
  ASSERT_EQ(log.scans.size(), 1u);
  EXPECT_EQ(log.scans[0].ranges.size(), 180u);
}

TEST(CarmenReader, RawLaserGetsOdometryInterpolatedToItsTime) {
  const std::string text =
      "PARAM robot_frontlaser_offset 0.1 nohost 0\n"
      "ODOM 0 0 0 0 0 0 10.0 h 10.0\n"
      "ODOM 1 0 0.2 0 0 0 11.0 h 11.0\n"
      "RAWLASER1 0 -1.570796 3.141593 0.008727 81.92 0.05 0 3 1 1 1 0 10.25 h 10.25\n";
  const LaserScan s = read_text(text).scans.at(0);
  EXPECT_NEAR(s.odometry.theta, 0.05, 1e-9);
  EXPECT_NEAR(s.odometry.x, 0.25, 0.01);
  EXPECT_DOUBLE_EQ(s.laser_offset.x, 0.1);
}

TEST(CarmenReader, ReadsGzipDirectly) {
  test::TempPath f(".log.gz");
  gzFile gz = gzopen(f.str().c_str(), "wb");
  const std::string text = "# comment\n" + flaser(360, 1.0) + flaser(360, 2.0);
  gzwrite(gz, text.data(), static_cast<unsigned>(text.size()));
  gzclose(gz);
  EXPECT_EQ(read_carmen_log(f.str()).scans.size(), 2u);
}

TEST(CarmenReader, MalformedLineNamesFileLineAndField) {
  const std::string bad = "FLASER 3 1.0 oops 1.0 0 0 0 0 0 0 3.0 h 3.0\n";
  test::TempPath f(".log");
  f.write(flaser(180, 1.0) + bad + flaser(180, 4.0));  // a bad line with more after it
  try {
    read_carmen_log(f.str());
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), f.str());
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "range");
    EXPECT_EQ(e.value(), "oops");
    EXPECT_NE(std::string(e.what()).find(":2:"), std::string::npos);
  }
}

TEST(CarmenReader, SkipBadLinesCountsThemAndKeepsTheRest) {
  LogReadOptions o;
  o.skip_bad_lines = true;
  const LaserLog log = read_text(flaser(180, 1.0) + "FLASER 9 1 2\n" + "ODOM 1 2\n" + flaser(180, 2.0), o);
  EXPECT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.bad_lines, 2u);
  EXPECT_NE(log.first_bad_line_message.find(":2:"), std::string::npos);
}

TEST(CarmenReader, TruncatedLastLineKeepsTheScansAndSaysWhere) {
  const std::string full = flaser(180, 1.0) + flaser(180, 2.0) + flaser(180, 3.0);
  const LaserLog log = read_text(full.substr(0, full.size() - 40));  // cut inside line 3
  EXPECT_EQ(log.scans.size(), 2u);
  EXPECT_NE(log.stopped_early.find(":3:"), std::string::npos) << log.stopped_early;
  EXPECT_EQ(read_text(full).stopped_early, "");
}

TEST(CarmenReader, OdometryJumpResetsTheMotionModel) {
  // The third scan's odometry reads 100 km further and the fourth's jumps back: a reset
  // odometer twice, not motion.
  const std::string jump = "FLASER 3 1 1 1 100000.0 2.0 0.0 100000.1 2.0 0.0 3.0 h -97\n";
  const LaserLog log = read_text(flaser(3, 1.0) + flaser(3, 2.0) + jump + flaser(3, 4.0));
  ASSERT_EQ(log.scans.size(), 4u);
  EXPECT_EQ(log.odometry_jumps.count, 2u);
  EXPECT_NE(log.odometry_jumps.first.find(":3:"), std::string::npos) << log.odometry_jumps.first;
  EXPECT_NEAR(log.scans[2].odometry.x, log.scans[1].odometry.x, 1e-9);  // the jump counts as no motion
  EXPECT_NEAR(log.scans[3].odometry.x, log.scans[2].odometry.x, 1e-9);  // and so does the jump back
}

TEST(CarmenReader, MissingFileIsAParseError) { EXPECT_THROW(read_carmen_log("/nonexistent/dir/x.log"), ParseError); }

// Fuzz: garbage and mutated valid lines either parse or raise ParseError; never a crash,
// never another exception, and with skip_bad_lines never an exception at all.
TEST(CarmenReader, FuzzedInputNeverCrashes) {
  std::mt19937_64 rng(2024);
  const std::string valid = flaser(10, 1.0) + "ROBOTLASER1 0 -1.57 3.14 0.349 50 0.1 0 10 " + ranges(10, "1.0") +
                            "0 1 2 0.1 1 2 0.1 0 0 0.5 0.3 1 55.5 h 5.5\nODOM 1 2 3 0 0 0 4 h 4\n";
  const std::string alphabet = "0123456789 .-+eEnaif\tFLASERODOM#\n\r\x01\xff";
  for (int trial = 0; trial < 400; ++trial) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(rng() % 12);
    for (int e = 0; e < edits; ++e) {
      const std::size_t pos = rng() % (text.size() + 1);
      switch (rng() % 3) {
        case 0:
          text.insert(pos, 1, alphabet[rng() % alphabet.size()]);
          break;
        case 1:
          if (pos < text.size()) text.erase(pos, 1 + rng() % 8);
          break;
        default:
          if (pos < text.size()) text[pos] = alphabet[rng() % alphabet.size()];
      }
    }
    try {
      read_text(text);
    } catch (const ParseError&) {
    } catch (const std::exception& e) {
      FAIL() << "unexpected exception " << e.what() << " on input:\n" << text;
    }
    LogReadOptions skip;
    skip.skip_bad_lines = true;
    EXPECT_NO_THROW(read_text(text, skip));
  }
}

}  // namespace
}  // namespace lookahead::slam
