// SPDX-License-Identifier: MIT
// plan() with what a grid search already knows: a goal in line of sight is the straight
// segment, and a known path length (cost_bound) confines the samples to its ellipse.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/planner/plan.hpp"
#include "test_worlds.hpp"

namespace lookahead::planner {
namespace {

using slam::OccupancyGrid;
using slam::Pose2;

PlannerOptions sample_limited(PlannerAlgorithm algorithm, int samples) {
  set_ompl_log_level(OmplLogLevel::kWarn);
  PlannerOptions o;
  o.algorithm = algorithm;
  o.time_budget = 20.0;
  o.max_samples = samples;
  return o;
}

TEST(PlanBounded, GoalInLineOfSightIsTheStraightSegment) {
  const OccupancyGrid g = testing::walled_room();
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.0, 2.0, sample_limited(PlannerAlgorithm::kRrtStar, 3000));
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_EQ(r.path.size(), 2u);
  EXPECT_EQ(r.path.back(), (Point2{3.0, 2.0}));
  EXPECT_NEAR(r.length, std::hypot(2.5, 1.5), 1e-9);
  EXPECT_EQ(r.states, 0u);  // no search ran
}

TEST(PlanBounded, WallInTheWayStillSearches) {
  const OccupancyGrid g = testing::corridor_with_gap();
  const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, sample_limited(PlannerAlgorithm::kRrtStar, 3000));
  ASSERT_TRUE(r.solved()) << r.message;
  EXPECT_GE(r.path.size(), 3u);
  EXPECT_GT(r.states, 10u);
}

// Through the gap and back is about 6.5 m; with that bound known, every planner finds the
// way with a fraction of the samples it needs over the whole room, and never returns a
// path longer than the bound.
TEST(PlanBounded, CostBoundFindsTheGapWithFewSamples) {
  const OccupancyGrid g = testing::corridor_with_gap();
  for (const PlannerAlgorithm a :
       {PlannerAlgorithm::kRrtStar, PlannerAlgorithm::kPrmStar, PlannerAlgorithm::kInformedRrtStar}) {
    PlannerOptions o = sample_limited(a, 400);
    o.cost_bound = 7.0;
    const PlanResult r = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
    ASSERT_TRUE(r.solved()) << to_string(a) << ": " << r.message;
    EXPECT_LE(r.length, 7.0 + 1e-6) << to_string(a);
    const Costmap c(g, o.costmap);
    EXPECT_TRUE(c.path_is_free(r.path)) << to_string(a);
  }
}

// samples_per_m2 sizes the search by the ellipse: a thin ellipse gets the floor.
TEST(PlanBounded, SampleDensityScalesTheSearch) {
  const OccupancyGrid g = testing::corridor_with_gap();
  PlannerOptions o = sample_limited(PlannerAlgorithm::kPrmStar, 100000);
  o.cost_bound = 7.0;
  o.samples_per_m2 = 1.0;  // ellipse ~ 13 m^2: the floor of kMinBoundedSamples applies
  const PlanResult few = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  o.samples_per_m2 = 300.0;  // ~ 4000 samples
  const PlanResult many = plan(g, Pose2{0.5, 0.5, 0.0}, 3.5, 0.5, o);
  ASSERT_TRUE(few.solved()) << few.message;
  ASSERT_TRUE(many.solved()) << many.message;
  EXPECT_LE(few.states, static_cast<std::size_t>(kMinBoundedSamples));
  EXPECT_GT(many.states, 3 * few.states);
}

TEST(PlanBounded, RejectsNegativeBounds) {
  PlannerOptions o;
  o.cost_bound = -1.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
  o = {};
  o.samples_per_m2 = -1.0;
  EXPECT_THROW(validate(o), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::planner
