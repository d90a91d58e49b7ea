// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/scan_landmarks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::slam::hybrid {
namespace {

// A room corner at (4, 3) (walls x = 4 for y >= 0 and y = 3) and a free-standing wall
// y = -2 for x in [1, 3], seen from the origin with a 180 deg, 0.5 deg laser. Expected: one
// corner at (4, 3); line ends at (1, -2), (3, -2) and (4, 0) (the wall x = 4 starts there,
// with nothing behind its end); none at the field-of-view edge.
LaserScan corner_scan() {
  LaserScan s;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 360;
  s.max_range = 30.0;
  for (int i = 0; i <= 360; ++i) {
    const double a = s.bearing(static_cast<std::size_t>(i)), c = std::cos(a), sn = std::sin(a);
    double r = 30.0;  // no return
    if (sn < -1e-9 && c > 1e-9) {
      const double t = -2.0 / sn;
      if (t * c >= 1.0 && t * c <= 3.0) r = t;
    } else if (sn >= 0.0) {
      const double to_x = c > 1e-9 ? 4.0 / c : INFINITY, to_y = sn > 1e-9 ? 3.0 / sn : INFINITY;
      r = std::min(to_x, to_y);
    }
    s.ranges.push_back(static_cast<float>(r));
  }
  return s;
}

int near(const std::vector<ScanLandmark>& l, ScanLandmark::Kind kind, double x, double y, double tol) {
  int n = 0;
  for (const auto& m : l) n += m.kind == kind && (m.point - Eigen::Vector2d(x, y)).norm() < tol;
  return n;
}

TEST(ScanLandmarks, FindsTheCornerAndTheFreeLineEnds) {
  const auto l = extract_scan_landmarks(corner_scan(), {});
  EXPECT_EQ(near(l, ScanLandmark::Kind::kCorner, 4.0, 3.0, 0.05), 1);
  EXPECT_EQ(near(l, ScanLandmark::Kind::kLineEnd, 1.0, -2.0, 0.1), 1);
  EXPECT_EQ(near(l, ScanLandmark::Kind::kLineEnd, 3.0, -2.0, 0.1), 1);
  EXPECT_EQ(near(l, ScanLandmark::Kind::kLineEnd, 4.0, 0.0, 0.1), 1);
  EXPECT_EQ(l.size(), 4u);
}

TEST(ScanLandmarks, LaserOffsetMovesLandmarksIntoTheRobotFrame) {
  LaserScan s = corner_scan();
  s.laser_offset = {0.5, 0.0, 0.0};
  const auto l = extract_scan_landmarks(s, {});
  EXPECT_EQ(near(l, ScanLandmark::Kind::kCorner, 4.5, 3.0, 0.05), 1);
}

// A wall y = 1.5 m from x = 1 on to x = 40, beyond the 15 m landmark range: its true end
// (1, 1.5) has nothing behind it; far out the grazing beams step farther apart than the
// break distance and the occlusion margin, which without the continuation rule reads as
// a second, false end.
TEST(ScanLandmarks, NoLineEndWhereTheWallContinues) {
  constexpr double kWallY = 1.5;
  LaserScan s;
  s.angle_min = -M_PI / 2;
  s.angle_increment = M_PI / 360;
  s.max_range = 30.0;
  for (int i = 0; i <= 360; ++i) {
    const double a = s.bearing(static_cast<std::size_t>(i)), sn = std::sin(a);
    const double t = sn > 1e-9 ? kWallY / sn : INFINITY;
    const bool hit = std::isfinite(t) && t * std::cos(a) >= 1.0 && t * std::cos(a) <= 40.0;
    s.ranges.push_back(static_cast<float>(hit ? t : 30.0));
  }
  ScanLandmarkOptions o;
  const auto far_ends = [](const std::vector<ScanLandmark>& l) {
    int n = 0;
    for (const auto& m : l) n += m.kind == ScanLandmark::Kind::kLineEnd && m.point.x() > 3.0;
    return n;
  };
  const auto without = extract_scan_landmarks(s, o);
  EXPECT_EQ(near(without, ScanLandmark::Kind::kLineEnd, 1.0, kWallY, 0.1), 1);
  EXPECT_GE(far_ends(without), 1) << "the scene should produce the false end this rule removes";
  o.continuation_distance = 0.1;
  const auto with = extract_scan_landmarks(s, o);
  EXPECT_EQ(near(with, ScanLandmark::Kind::kLineEnd, 1.0, kWallY, 0.1), 1);
  EXPECT_EQ(far_ends(with), 0);
}

TEST(ScanLandmarks, ObservationCarriesTheCovariance) {
  ScanLandmark l{ScanLandmark::Kind::kCorner, {0.0, 10.0}, Eigen::Matrix2d::Identity() * 0.0025};
  const RangeBearing z = to_observation(l);
  EXPECT_NEAR(z.range, 10.0, 1e-12);
  EXPECT_NEAR(z.bearing, M_PI / 2, 1e-12);
  EXPECT_NEAR(z.noise(0, 0), 0.0025, 1e-12);          // along the beam: 5 cm
  EXPECT_NEAR(z.noise(1, 1), 0.0025 / 100.0, 1e-12);  // across: 5 cm at 10 m
}

}  // namespace
}  // namespace lookahead::slam::hybrid
