// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/interpolated_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::slam {
namespace {

using Updates = std::vector<std::pair<std::size_t, Pose2>>;

MotionSinceUpdate by_odometry(const std::vector<Pose2>& odometry) {
  return [&odometry](std::size_t a, std::size_t s) { return odometry[a].between(odometry[s]); };
}

bool none_placed(std::size_t) { return false; }

// Updates that agree with the odometry leave the odometry's path as it is.
TEST(InterpolatedTrajectory, UpdatesOnTheOdometryKeepItsPath) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0.1}, {2, 0.1, 0.2}, {3, 0.3, 0.3}, {4, 0.6, 0.4}};
  const Updates updates{{0, odometry[0]}, {4, odometry[4]}};
  const std::vector<Pose2> out =
      interpolate_between_updates(updates, odometry, by_odometry(odometry), none_placed, 2.0);
  ASSERT_EQ(out.size(), odometry.size());
  for (std::size_t s = 0; s < out.size(); ++s) {
    EXPECT_NEAR(out[s].x, odometry[s].x, 1e-12);
    EXPECT_NEAR(out[s].y, odometry[s].y, 1e-12);
    EXPECT_NEAR(out[s].theta, odometry[s].theta, 1e-12);
  }
}

// Odometry that under-reads a turn: the correction the next update makes is spread along
// the travel, half of it at half the way, and the interval ends on the update's pose.
TEST(InterpolatedTrajectory, CorrectionIsSpreadAlongTheTravel) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  const Updates updates{{0, {0, 0, 0}}, {4, {4, 0.4, 0.2}}};
  const std::vector<Pose2> out =
      interpolate_between_updates(updates, odometry, by_odometry(odometry), none_placed, 2.0);
  EXPECT_NEAR(out[2].x, 2.0, 1e-12);
  EXPECT_NEAR(out[2].y, 0.2, 1e-12);
  EXPECT_NEAR(out[2].theta, 0.1, 1e-12);
  EXPECT_NEAR(out[4].y, 0.4, 1e-12);
  EXPECT_NEAR(out[4].theta, 0.2, 1e-12);
}

// A turn on the spot travels no distance: the turn itself (metres_per_radian) sets the share.
TEST(InterpolatedTrajectory, TurnOnTheSpotSpreadsByTheTurn) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {0, 0, 0.3}, {0, 0, 0.4}};
  const Updates updates{{0, {0, 0, 0}}, {2, {0, 0, 0.6}}};
  const std::vector<Pose2> out =
      interpolate_between_updates(updates, odometry, by_odometry(odometry), none_placed, 2.0);
  EXPECT_NEAR(out[1].theta, 0.3 + 0.75 * 0.2, 1e-12);  // 0.3 of 0.4 rad turned: 3/4 of the correction
}

// Scans after the last update follow the given motion; no update gives no trajectory.
TEST(InterpolatedTrajectory, AfterTheLastUpdateFollowsTheMotion) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const Updates updates{{0, {5, 5, M_PI / 2}}};
  const std::vector<Pose2> out =
      interpolate_between_updates(updates, odometry, by_odometry(odometry), none_placed, 2.0);
  EXPECT_NEAR(out[2].x, 5.0, 1e-12);
  EXPECT_NEAR(out[2].y, 7.0, 1e-12);
  EXPECT_TRUE(interpolate_between_updates({}, odometry, by_odometry(odometry), none_placed, 2.0).empty());
}

// A scan matched on the way keeps its own estimate: the correction the next update makes is
// not spread over it (it would turn a good heading into a ramp towards the update's).
TEST(InterpolatedTrajectory, APlacedScanKeepsItsEstimate) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<Pose2> matched{{0, 0, 0}, {1, 0.1, 0.05}, {}};
  const MotionSinceUpdate motion = [&](std::size_t a, std::size_t s) {
    return s == 1 ? matched[1] : odometry[a].between(odometry[s]);
  };
  const Updates updates{{0, {0, 0, 0}}, {2, {2, 0, 0}}};
  const std::vector<Pose2> out = interpolate_between_updates(
      updates, odometry, motion, [](std::size_t s) { return s == 1; }, 2.0);
  EXPECT_NEAR(out[1].y, 0.1, 1e-12);
  EXPECT_NEAR(out[1].theta, 0.05, 1e-12);
  EXPECT_NEAR(out[2].y, 0.0, 1e-12);
}

// Scans no estimate placed lie on the odometry from the estimate before them, bent onto the
// estimate after them: a placed scan ends one gap and starts the next.
TEST(InterpolatedTrajectory, GapsBendBetweenTheEstimatesAroundThem) {
  const std::vector<Pose2> odometry{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  // scan 2 matched 0.2 to the left; scans 1 and 3 follow the odometry chained from before them
  const std::vector<Pose2> since{{0, 0, 0}, {1, 0, 0}, {2, 0.2, 0}, {3, 0.2, 0}, {}};
  const MotionSinceUpdate motion = [&](std::size_t, std::size_t s) { return since[s]; };
  const Updates updates{{0, {0, 0, 0}}, {4, {4, 0.4, 0}}};
  const std::vector<Pose2> out = interpolate_between_updates(
      updates, odometry, motion, [](std::size_t s) { return s == 2; }, 2.0);
  EXPECT_NEAR(out[1].y, 0.1, 1e-12);  // half way from (0, 0) to the match's 0.2
  EXPECT_NEAR(out[2].y, 0.2, 1e-12);
  EXPECT_NEAR(out[3].y, 0.3, 1e-12);  // half way from the match's 0.2 to the update's 0.4
  EXPECT_NEAR(out[4].y, 0.4, 1e-12);
}

}  // namespace
}  // namespace lookahead::slam
