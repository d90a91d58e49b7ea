// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/relative_error.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lookahead/slam/eval/absolute_error.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "temp_file.hpp"

namespace lookahead::slam {
namespace {

TEST(RelativeError, PerfectTrajectoryScoresZero) {
  std::vector<StampedPose> t;
  for (int i = 0; i < 10; ++i) t.push_back({1.0 * i, {0.5 * i, 0.1 * i * i, 0.2 * i}});
  const RelativeError e = relative_error(relations_from_reference(t, 2), t);
  EXPECT_EQ(e.used, 8u);
  EXPECT_NEAR(e.trans_mean, 0.0, 1e-12);
  EXPECT_NEAR(e.rot_mean, 0.0, 1e-9);
}

TEST(RelativeError, KnownOffsetAndUnmatchedStamps) {
  const std::vector<StampedPose> t{{0.0, {0, 0, 0}}, {1.0, {1.1, 0, 0}}};
  const std::vector<Relation> r{{0.0, 1.0, {1.0, 0, 0}}, {0.0, 5.0, {1.0, 0, 0}}};
  const RelativeError e = relative_error(r, t);
  EXPECT_EQ(e.used, 1u);
  EXPECT_EQ(e.skipped, 1u);
  EXPECT_NEAR(e.trans_mean, 0.1, 1e-12);
}

TEST(AbsoluteError, RigidlyMovedTrajectoryAlignsToZero) {
  std::vector<StampedPose> ref, est;
  const Pose2 move{3.0, -2.0, 0.7};
  for (int i = 0; i < 20; ++i) {
    const Pose2 p{0.3 * i, std::sin(0.4 * i), 0.1 * i};
    ref.push_back({1.0 * i, p});
    est.push_back({1.0 * i, move.compose(p)});
  }
  const AbsoluteError a = absolute_trajectory_error(ref, est);
  EXPECT_EQ(a.matched, 20u);
  EXPECT_NEAR(a.rmse, 0.0, 1e-9);
}

TEST(RelativeError, GarbageFilesNameFileLineAndField) {
  test::TempPath rel(".relations");
  rel.write("1 2 0 0 0 0 0 0\n1 2 x 0 0 0 0 0\n");
  try {
    read_relations(rel.str());
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.field(), "x");
    EXPECT_EQ(e.value(), "x");
  }
  test::TempPath traj(".txt");
  traj.write("# timestamp x y theta\n0 1 2\n");
  EXPECT_THROW(read_trajectory(traj.str()), ParseError);
  EXPECT_THROW(read_relations("/no/such/file"), ParseError);
}

}  // namespace
}  // namespace lookahead::slam
