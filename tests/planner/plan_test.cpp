// SPDX-License-Identifier: MIT
#include "lookahead/planner/plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lookahead/planner/ompl_logging.hpp"
#include "test_worlds.hpp"

namespace lookahead::planner {
namespace {

using slam::OccupancyGrid;
using slam::Pose2;

constexpr PlannerAlgorithm kAll[] = {PlannerAlgorithm::kRrtStar, PlannerAlgorithm::kPrmStar,
                                     PlannerAlgorithm::kInformedRrtStar};

/// Generous time, a sample limit that ends the search: repeatable and fast.
PlannerOptions sample_limited(PlannerAlgorithm algorithm, int samples = 3000) {
  set_ompl_log_level(OmplLogLevel::kWarn);
  PlannerOptions o;
  o.algorithm = algorithm;
  o.time_budget = 20.0;
  o.max_samples = samples;
  return o;
}

class EachPlanner : public ::testing::TestWithParam<PlannerAlgorithm> {};

TEST_P(EachPlanner, SolvesCorridorWithGapAvoidingTheWall) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlannerOptions o = sample_limited(GetParam());
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  ASSERT_EQ(r.status, PlanStatus::kSolved) << r.message;
  EXPECT_EQ(r.algorithm, GetParam());
  ASSERT_GE(r.path.size(), 3u);
  EXPECT_EQ(r.path.front(), (Point2{0.5, 0.5}));
  EXPECT_EQ(r.path.back(), (Point2{3.5, 0.5}));
  EXPECT_NEAR(r.length, path_length(r.path), 1e-9);
  EXPECT_GT(r.states, 10u);
  EXPECT_EQ(r.guard_rejections, 0u);
  // Independent check: no segment meets an inflated wall cell.
  const Costmap extent(g, o.costmap);
  const testing::Oracle oracle = testing::brute_force_costmap(g, extent, o.costmap);
  EXPECT_TRUE(oracle.path_free(r.path));
  // The only way round is through the gap, y in [2.0, 2.8] m.
  double top = 0.0;
  for (const Point2& p : r.path) top = std::max(top, p.y);
  EXPECT_GT(top, 2.0);
  // Straight down, up through the gap and back is about 2 * 1.75 + 3 = 6.5 m.
  EXPECT_LT(r.length, 9.0);
}

TEST_P(EachPlanner, SameSeedSamePath) {
  const OccupancyGrid g = testing::corridor_with_gap();
  PlannerOptions o = sample_limited(GetParam(), 1500);
  o.seed = 42;
  const PlanResult a = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  o.seed = 43;  // an unrelated call in between must not disturb the next one
  const PlanResult other = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  o.seed = 42;
  const PlanResult b = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  ASSERT_TRUE(a.solved()) << a.message;
  ASSERT_TRUE(other.solved()) << other.message;
  EXPECT_EQ(a.path, b.path);
  EXPECT_EQ(a.states, b.states);
  EXPECT_NE(a.path, other.path);
}

INSTANTIATE_TEST_SUITE_P(Planner, EachPlanner, ::testing::ValuesIn(kAll),
                         [](const ::testing::TestParamInfo<PlannerAlgorithm>& info) {
                           return std::string(to_string(info.param));
                         });

TEST(Plan, UnreachableGoalIsNoPath) {
  const OccupancyGrid g = testing::corridor_with_gap(false);
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, sample_limited(PlannerAlgorithm::kRrtStar));
  EXPECT_EQ(r.status, PlanStatus::kNoPath);
  EXPECT_TRUE(r.path.empty());
  EXPECT_LT(r.planning_time, 1.0) << "the flood fill answers without spending the budget";
}

TEST(Plan, GoalInWallIsGoalBlocked) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 2.0, 0.5, sample_limited(PlannerAlgorithm::kRrtStar));
  EXPECT_EQ(r.status, PlanStatus::kGoalBlocked);
  // Within the robot radius of a wall counts as in it.
  EXPECT_EQ(plan(g, Pose2{0.5, 0.5, 0.0}, 1.75, 0.5, sample_limited(PlannerAlgorithm::kRrtStar)).status,
            PlanStatus::kGoalBlocked);
  // Unknown space is blocked by default.
  EXPECT_EQ(plan(g, Pose2{0.5, 0.5, 0.0}, 10.0, 0.5, sample_limited(PlannerAlgorithm::kRrtStar)).status,
            PlanStatus::kGoalBlocked);
}

TEST(Plan, StartInWallIsStartBlocked) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlanResult r = plan(g, Pose2{2.0, 0.5, 0.0}, 3.5, 0.5, sample_limited(PlannerAlgorithm::kRrtStar));
  EXPECT_EQ(r.status, PlanStatus::kStartBlocked);
}

TEST(Plan, NonFiniteInputOrEmptyMapIsInvalidInput) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlannerOptions o = sample_limited(PlannerAlgorithm::kRrtStar);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(plan(g, Pose2{0.5, 0.5, 0.0}, nan, 0.5, o).status, PlanStatus::kInvalidInput);
  EXPECT_EQ(plan(g, Pose2{nan, 0.5, 0.0}, 3.5, 0.5, o).status, PlanStatus::kInvalidInput);
  EXPECT_EQ(plan(OccupancyGrid{}, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o).status, PlanStatus::kInvalidInput);
}

TEST(Plan, TooFewSamplesIsNoPathNotAnApproximatePath) {
  // Reachable, but 20 samples cannot get through the gap: OMPL then has an approximate
  // solution only, which must not come back as solved.
  const OccupancyGrid g = testing::corridor_with_gap();
  for (const PlannerAlgorithm a : kAll) {
    const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, sample_limited(a, 20));
    EXPECT_EQ(r.status, PlanStatus::kNoPath) << to_string(a);
    EXPECT_TRUE(r.path.empty());
  }
}

TEST(Plan, TimeBudgetIsRespected) {
  const OccupancyGrid g = testing::corridor_with_gap();
  for (const PlannerAlgorithm a : kAll) {
    PlannerOptions o = sample_limited(a);
    o.max_samples = 0;  // the clock alone ends these anytime searches
    o.time_budget = 0.2;
    const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
    EXPECT_TRUE(r.solved()) << to_string(a) << ": " << r.message;
    EXPECT_GE(r.planning_time, 0.2 * 0.9) << to_string(a);
    EXPECT_LT(r.planning_time, 0.2 + 2.0) << to_string(a);  // generous: loaded CI machines
  }
}

TEST(Plan, GoalWithinToleranceOfStartIsTrivial) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 0.55, 0.5, sample_limited(PlannerAlgorithm::kRrtStar));
  ASSERT_TRUE(r.solved());
  EXPECT_EQ(r.path.size(), 2u);
}

TEST(Plan, CostmapOverloadMatchesGridOverload) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlannerOptions o = sample_limited(PlannerAlgorithm::kRrtStar, 1000);
  const Costmap c(g, o.costmap);
  EXPECT_EQ(plan(c, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o).path, plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o).path);
}

TEST(PlannerOptions, RejectsOutOfRangeValues) {
  PlannerOptions o;
  EXPECT_NO_THROW(validate(o));
  o.time_budget = 0.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.goal_bias = 1.5;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.max_samples = -1;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.costmap.robot_radius = 9.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.algorithm = static_cast<PlannerAlgorithm>(17);
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.goal_tolerance = -0.1;
  EXPECT_THROW((void)plan(testing::corridor_with_gap(), Pose2{}, 1.0, 1.0, o), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::planner
