// SPDX-License-Identifier: MIT
#include "lookahead/slam/geometry/pose2.hpp"

#include <gtest/gtest.h>

#include <random>

namespace lookahead::slam {
namespace {

TEST(Pose2, NormalizeAngleStaysInHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(normalize_angle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(normalize_angle(-M_PI), M_PI);
  EXPECT_NEAR(normalize_angle(3 * M_PI + 0.1), -M_PI + 0.1, 1e-12);
  EXPECT_NEAR(normalize_angle(-0.3), -0.3, 1e-15);
}

TEST(Pose2, ComposeWithInverseIsIdentity) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 200; ++i) {
    const Pose2 p{u(rng), u(rng), normalize_angle(u(rng))};
    const Pose2 id = p.compose(p.inverse());
    EXPECT_NEAR(id.x, 0, 1e-9);
    EXPECT_NEAR(id.y, 0, 1e-9);
    EXPECT_NEAR(id.theta, 0, 1e-9);
  }
}

TEST(Pose2, BetweenRecoversRelativeMotion) {
  const Pose2 a{1, 2, M_PI / 2};
  const Pose2 d{0.5, -0.2, 0.3};
  const Pose2 b = a.compose(d);
  EXPECT_NEAR(b.x, 1.2, 1e-12);  // forward along +y, right is +x
  EXPECT_NEAR(b.y, 2.5, 1e-12);
  const Pose2 r = a.between(b);
  EXPECT_NEAR(r.x, d.x, 1e-12);
  EXPECT_NEAR(r.y, d.y, 1e-12);
  EXPECT_NEAR(r.theta, d.theta, 1e-12);
}

}  // namespace
}  // namespace lookahead::slam
