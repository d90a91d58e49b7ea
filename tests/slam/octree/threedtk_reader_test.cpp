// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/threedtk_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "../temp_file.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

const std::string kDat = std::string(LOOKAHEAD_SOURCE_DIR) + "/../shared/data/3d/3dtk_dat";

TEST(ThreeDtkReader, ReadsTheRealScansAndConvertsTheFrame) {
  const RangeLog3 log = read_3dtk_folder(kDat);
  ASSERT_EQ(log.sweeps.size(), 3U);
  for (const RangeSweep& s : log.sweeps) {
    EXPECT_EQ(s.rays.size(), 81360U);  // SOURCES.md: exactly 81,360 points per scan
    std::size_t no_return = 0;
    for (const Ray3& r : s.rays) {
      no_return += r.hit ? 0 : 1;
      EXPECT_GE(r.end.x(), -1e-9);  // a 180 deg sweep: 3DTK z >= 0 is our x >= 0
    }
    const double share = static_cast<double>(no_return) / static_cast<double>(s.rays.size());
    EXPECT_GT(share, 0.015);
    EXPECT_LT(share, 0.021);
  }
  // scan001.pose: -3.10605 -7.50803 156.917 cm (x right, y up, z forward) -> forward
  // 1.569 m, left 0.031 m, down 0.075 m.
  const Eigen::Vector3d p = log.sweeps[1].odometry.translation();
  EXPECT_NEAR(p.x(), 1.56917, 1e-9);
  EXPECT_NEAR(p.y(), 0.0310605, 1e-9);
  EXPECT_NEAR(p.z(), -0.0750803, 1e-9);
  EXPECT_NEAR(std::abs(log.sweeps[1].odometry.linear().determinant() - 1.0), 0.0, 1e-9);
}

class ThreeDtkFiles : public ::testing::Test {
 protected:
  void write(const std::string& scan, const std::string& pose) {
    scan_.write(scan);
    pose_.write(pose);
  }
  RangeSweep read() { return read_3dtk_scan(scan_.str(), pose_.str()); }
  test::TempPath scan_{".3d"}, pose_{".pose"};
};

TEST_F(ThreeDtkFiles, BadNumberNamesFileLineFieldAndValue) {
  write("100 0 200\n1 2 3\n5 abc 7\n", "0 0 0\n0 0 0\n");
  try {
    read();
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), scan_.str());
    EXPECT_EQ(e.line(), 3U);
    EXPECT_EQ(e.field(), "y");
    EXPECT_EQ(e.value(), "abc");
  }
}

TEST_F(ThreeDtkFiles, MissingValueAndShortPoseAreErrors) {
  write("1 2\n", "0 0 0\n0 0 0\n");
  EXPECT_THROW(read(), ParseError);
  write("1 2 3\n", "0 0 0\n");
  try {
    read();
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), pose_.str());
    EXPECT_EQ(e.field(), "theta_x");
  }
  write("1 2 3\n", "0 0 nan\n0 0 0\n");
  EXPECT_THROW(read(), ParseError);
  EXPECT_THROW(read_3dtk_scan("/nonexistent/scan000.3d", pose_.str()), ParseError);
  EXPECT_THROW(read_3dtk_folder("/nonexistent"), ParseError);
}

TEST_F(ThreeDtkFiles, ExtraColumnsAndBlankLinesAreAccepted) {
  write("100 0 200 17\n\n-100 50 300 3\n", "\n0 0 0\n0 0 0\n");
  const RangeSweep s = read();
  ASSERT_EQ(s.rays.size(), 2U);
  EXPECT_NEAR(s.rays[1].end.x(), 3.0, 1e-12);  // z forward
  EXPECT_NEAR(s.rays[1].end.y(), 1.0, 1e-12);  // -x: 3DTK's x points right
  EXPECT_NEAR(s.rays[1].end.z(), 0.5, 1e-12);  // y up
}

// Fuzz: random byte edits of a valid scan either parse or raise ParseError; nothing else.
TEST_F(ThreeDtkFiles, MutatedFilesParseOrRaiseParseError) {
  const std::string valid = "12.5 -3 400\n7 8 9\n-1e2 2.5e1 3\n";
  const std::string alphabet = "0123456789 .-+eE\nx\t";
  std::mt19937 rng(42);
  int errors = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::string text = valid;
    for (int edits = 1 + static_cast<int>(rng() % 4); edits > 0; --edits) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0:
          text[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1);
          break;
        default:
          text.insert(at, 1, alphabet[rng() % alphabet.size()]);
      }
    }
    write(text, "0 0 0\n0 0 0\n");
    try {
      for (const Ray3& r : read().rays) ASSERT_TRUE(r.end.allFinite());
    } catch (const ParseError& e) {
      ++errors;
      EXPECT_GE(e.line(), 1U);
      EXPECT_FALSE(e.field().empty());
    }
  }
  EXPECT_GT(errors, 50);  // the mutations do break files
}

// Property: any finite numbers written out read back, converted to metres in our frame.
TEST_F(ThreeDtkFiles, RandomPointsRoundTrip) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5000.0, 5000.0);
  std::string text;
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    points.push_back(p);
    text += fmt::format("{} {} {}\n", p.x(), p.y(), p.z());
  }
  write(text, "0 0 0\n0 0 0\n");
  const RangeSweep s = read();
  ASSERT_EQ(s.rays.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(s.rays[i].end.x(), points[i].z() / 100, 1e-9);
    EXPECT_NEAR(s.rays[i].end.y(), -points[i].x() / 100, 1e-9);
    EXPECT_NEAR(s.rays[i].end.z(), points[i].y() / 100, 1e-9);
  }
}

}  // namespace
}  // namespace lookahead::slam
