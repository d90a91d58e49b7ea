// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/match_confirmation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lookahead::slam::segslam {
namespace {

// The world: the candidate's frame sits at `candidate_frame`, the particle's submap at
// `submap_frame`; a robot at world pose r is at candidate_frame^-1 r in the one and
// submap_frame^-1 r in the other.
struct World {
  Pose2 candidate_frame{12.0, -30.0, 0.7};
  Pose2 submap_frame{-25.0, 18.0, -1.9};
  [[nodiscard]] Pose2 in_candidate(const Pose2& r) const { return candidate_frame.inverse().compose(r); }
  [[nodiscard]] Pose2 in_submap(const Pose2& r) const { return submap_frame.inverse().compose(r); }
};

// Property: two right matches of one segment confirm each other wherever the robot went
// between them, and after the particle started a fresh submap in between.
TEST(MatchConfirmation, RightMatchesConfirmEachOther) {
  const World w;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> xy(-40, 40), th(-M_PI, M_PI);
  for (int k = 0; k < 200; ++k) {
    const Pose2 r1{xy(rng), xy(rng), th(rng)}, r2{xy(rng), xy(rng), th(rng)};
    const std::vector<PendingMatch> pending{pending_match(3, w.in_candidate(r1), w.in_submap(r1))};
    EXPECT_TRUE(confirms(pending, 3, w.in_candidate(r2), w.in_submap(r2), 0.01, 0.001));
    EXPECT_FALSE(confirms(pending, 4, w.in_candidate(r2), w.in_submap(r2), 0.01, 0.001)) << "another segment";
    // A fresh submap started at robot pose r_mid: its frame is that pose.
    const Pose2 r_mid{xy(rng), xy(rng), th(rng)};
    const std::vector<PendingMatch> carried{carried_into(pending.front(), w.in_submap(r_mid))};
    EXPECT_TRUE(confirms(carried, 3, w.in_candidate(r2), r_mid.inverse().compose(r2), 0.01, 0.001));
  }
}

// A match off by more than the tolerance where the robot is does not confirm, though the
// frames' origins (tens of metres away) would differ by metres for a small heading error:
// the test is where the robot is.
TEST(MatchConfirmation, ComparesWhereTheRobotIs) {
  const World w;
  const Pose2 r1{0, 0, 0.3}, r2{2.0, 0.5, 0.35};
  const std::vector<PendingMatch> pending{pending_match(1, w.in_candidate(r1), w.in_submap(r1))};
  const Pose2 right = w.in_candidate(r2);
  EXPECT_TRUE(confirms(pending, 1, right, w.in_submap(r2), 1.0, 0.2));
  // 0.15 rad off in heading: within 0.2 rad, outside 0.1 rad.
  const Pose2 turned{right.x, right.y, right.theta + 0.15};
  EXPECT_TRUE(confirms(pending, 1, turned, w.in_submap(r2), 1.0, 0.2));
  EXPECT_FALSE(confirms(pending, 1, turned, w.in_submap(r2), 1.0, 0.1));
  // 1.5 m off (an alias one doorway along).
  const Pose2 shifted{right.x + 1.5, right.y, right.theta};
  EXPECT_FALSE(confirms(pending, 1, shifted, w.in_submap(r2), 1.0, 0.2));
  EXPECT_FALSE(confirms({}, 1, right, w.in_submap(r2), 1.0, 0.2)) << "nothing pending";
}

}  // namespace
}  // namespace lookahead::slam::segslam
