// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/motion_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::slam {
namespace {

TEST(OdometryMotionModel, SamplesHaveTheModelledSpread) {
  const OdometryMotionModel m;  // srr 0.1, srt 0.2, str 0.1, stt 0.2
  std::mt19937_64 rng(11);
  const Pose2 start{1, 2, 0.5};
  const Pose2 u{1.0, 0.0, 0.0};
  double mx = 0, my = 0, mt = 0, vx = 0, vy = 0, vt = 0;
  constexpr int kN = 20000;
  for (int i = 0; i < kN; ++i) {
    const Pose2 d = start.between(m.sample(start, u, rng));
    mx += d.x;
    my += d.y;
    mt += d.theta;
    vx += (d.x - 1) * (d.x - 1);
    vy += d.y * d.y;
    vt += d.theta * d.theta;
  }
  EXPECT_NEAR(mx / kN, 1.0, 0.005);
  EXPECT_NEAR(my / kN, 0.0, 0.005);
  EXPECT_NEAR(mt / kN, 0.0, 0.005);
  EXPECT_NEAR(std::sqrt(vx / kN), 0.1, 0.005);   // srr * 1 m
  EXPECT_NEAR(std::sqrt(vy / kN), 0.03, 0.003);  // 0.3 srr * 1 m
  EXPECT_NEAR(std::sqrt(vt / kN), 0.2, 0.01);    // srt * 1 m
}

TEST(OdometryMotionModel, DensityPeaksAtTheOdometryPrediction) {
  const OdometryMotionModel m;
  const Pose2 start{0, 0, 1.0};
  const Pose2 u{0.5, 0.1, 0.2};
  const Pose2 predicted = start.compose(u);
  const double peak = m.log_density(start, u, predicted);
  EXPECT_NEAR(peak, 0.0, 1e-12);
  EXPECT_LT(m.log_density(start, u, {predicted.x + 0.05, predicted.y, predicted.theta}), peak);
  EXPECT_LT(m.log_density(start, u, {predicted.x, predicted.y, predicted.theta - 0.05}), peak);
}

TEST(OdometryMotionModel, RejectsNegativeNoise) {
  MotionModelOptions o;
  o.srt = -0.1;
  EXPECT_THROW(OdometryMotionModel{o}, std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam
