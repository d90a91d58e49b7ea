// SPDX-License-Identifier: MIT
#include "lookahead/predictor/map_features.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::predictor {
namespace {

// Walls drawn as occupied cells along a segment (5 cm cells).
void wall(slam::OccupancyGrid& g, double x0, double y0, double x1, double y1) {
  const int n = static_cast<int>(std::hypot(x1 - x0, y1 - y0) / 0.02) + 1;
  for (int i = 0; i <= n; ++i) {
    const double t = static_cast<double>(i) / n;
    const slam::CellIndex c = g.cell_at(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
    if (!g.is_obstacle(c)) g.add_log_odds(c, 3 * g.fixed_hit());
  }
}

double angle_diff(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }

TEST(MapFeatures, EmptyGridHasNoFeatures) {
  const MapFeatures f = extract_features(slam::OccupancyGrid{}, {});
  EXPECT_TRUE(f.lines.empty());
  EXPECT_TRUE(f.corners.empty());
}

TEST(MapFeatures, LShapedWallGivesOneCornerWithBothLineDirections) {
  slam::OccupancyGrid g;
  wall(g, 1.0, 1.0, 4.0, 1.0);  // along +x from the corner
  wall(g, 1.0, 1.0, 1.0, 3.0);  // along +y from the corner
  const MapFeatures f = extract_features(g, {});
  ASSERT_GE(f.lines.size(), 2u);
  ASSERT_EQ(f.corners.size(), 1u);
  const Corner& c = f.corners[0];
  EXPECT_NEAR(c.x, 1.0, 0.1);
  EXPECT_NEAR(c.y, 1.0, 0.1);
  const bool ab = angle_diff(c.angle_a, 0.0) < 0.05 && angle_diff(c.angle_b, M_PI / 2) < 0.05;
  const bool ba = angle_diff(c.angle_b, 0.0) < 0.05 && angle_diff(c.angle_a, M_PI / 2) < 0.05;
  EXPECT_TRUE(ab || ba) << c.angle_a << " " << c.angle_b;
}

TEST(MapFeatures, RotatedRoomHasFourCornersAtItsVertices) {
  slam::OccupancyGrid g;
  const double a = 0.5;  // about 29 degrees
  const auto p = [&](double u, double v) {
    return std::pair<double, double>{2 + u * std::cos(a) - v * std::sin(a), 2 + u * std::sin(a) + v * std::cos(a)};
  };
  const std::pair<double, double> v[4] = {p(0, 0), p(4, 0), p(4, 3), p(0, 3)};
  for (int i = 0; i < 4; ++i) wall(g, v[i].first, v[i].second, v[(i + 1) % 4].first, v[(i + 1) % 4].second);
  const MapFeatures f = extract_features(g, {});
  EXPECT_GE(f.lines.size(), 4u);
  ASSERT_EQ(f.corners.size(), 4u);
  for (const auto& [x, y] : v) {
    double best = 1e9;
    for (const Corner& c : f.corners) best = std::min(best, std::hypot(c.x - x, c.y - y));
    EXPECT_LT(best, 0.15) << x << "," << y;
  }
  for (const Corner& c : f.corners) EXPECT_NEAR(angle_diff(c.angle_a, c.angle_b), M_PI / 2, 0.06);
}

TEST(MapFeatures, ParallelWallsMakeNoCorner) {
  slam::OccupancyGrid g;
  wall(g, 0, 0, 5, 0);
  wall(g, 0, 2, 5, 2);
  EXPECT_TRUE(extract_features(g, {}).corners.empty());
}

TEST(MapFeatures, RejectsImpossibleOptions) {
  FeatureOptions o;
  o.occupied_threshold = 0.3;
  EXPECT_THROW(extract_features(slam::OccupancyGrid{}, o), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::predictor
