// SPDX-License-Identifier: MIT
// Fuzz: on random obstacle worlds and seeds, plan() never returns an invalid path, and says
// no_path exactly when a brute-force flood fill finds the goal unreachable.
#include <gtest/gtest.h>

#include <deque>
#include <random>

#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/planner/plan.hpp"
#include "test_worlds.hpp"

namespace lookahead::planner {
namespace {

using slam::OccupancyGrid;
using testing::Oracle;

constexpr int kSide = 60;  // cells: a 3 m x 3 m world

/// Random rectangles of wall in a free square, and in every other world a full-height wall
/// whose gap (0 to 9 cells) may be too narrow for the robot: unreachable goals for sure.
OccupancyGrid random_world(std::mt19937& rng, bool split) {
  OccupancyGrid g;
  testing::fill(g, 0, 0, kSide - 1, kSide - 1, false);
  std::uniform_int_distribution<int> corner(0, kSide - 1);
  std::uniform_int_distribution<int> size(1, 12);
  for (int i = 0; i < 14; ++i) {
    const int x = corner(rng);
    const int y = corner(rng);
    testing::fill(g, x, y, std::min(kSide - 1, x + size(rng)), std::min(kSide - 1, y + size(rng) / 4), true);
  }
  if (split) {
    const int x = std::uniform_int_distribution<int>(20, 40)(rng);
    const int gap = std::uniform_int_distribution<int>(0, 9)(rng);
    const int gap_y = std::uniform_int_distribution<int>(5, 45)(rng);
    testing::fill(g, x, 0, x + 1, kSide - 1, true);
    if (gap > 0) testing::fill(g, x, gap_y, x + 1, gap_y + gap - 1, false);
  }
  return g;
}

/// Brute-force reachability on the oracle raster (breadth-first, 4-connected).
bool oracle_reachable(const Oracle& o, slam::CellIndex from, slam::CellIndex to) {
  if (o.cell_blocked(from.x, from.y) || o.cell_blocked(to.x, to.y)) return false;
  std::vector<char> seen(static_cast<std::size_t>(o.width * o.height), 0);
  std::deque<slam::CellIndex> queue{from};
  seen[static_cast<std::size_t>((from.y - o.origin.y) * o.width + from.x - o.origin.x)] = 1;
  while (!queue.empty()) {
    const slam::CellIndex c = queue.front();
    queue.pop_front();
    if (c == to) return true;
    const slam::CellIndex next[4] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
    for (const slam::CellIndex n : next) {
      if (o.cell_blocked(n.x, n.y)) continue;
      char& s = seen[static_cast<std::size_t>((n.y - o.origin.y) * o.width + n.x - o.origin.x)];
      if (s) continue;
      s = 1;
      queue.push_back(n);
    }
  }
  return false;
}

/// A random position whose cell the oracle calls free.
Point2 random_free_position(const Oracle& o, std::mt19937& rng) {
  std::uniform_real_distribution<double> coord(0.0, kSide * o.resolution);
  for (int i = 0; i < 10000; ++i) {
    const Point2 p{coord(rng), coord(rng)};
    if (!o.cell_blocked(static_cast<int>(std::floor(p.x / o.resolution)),
                        static_cast<int>(std::floor(p.y / o.resolution)))) {
      return p;
    }
  }
  return {-1.0, -1.0};
}

TEST(PlanProperty, NeverReturnsAnInvalidPathOnRandomWorlds) {
  set_ompl_log_level(OmplLogLevel::kWarn);
  std::mt19937 rng(2024);
  const PlannerAlgorithm algorithms[] = {PlannerAlgorithm::kRrtStar, PlannerAlgorithm::kPrmStar,
                                         PlannerAlgorithm::kInformedRrtStar};
  int solved = 0;
  int unreachable = 0;
  for (int world = 0; world < 30; ++world) {
    const OccupancyGrid g = random_world(rng, world % 2 == 1);
    PlannerOptions o;
    o.costmap.robot_radius = 0.1;
    o.goal_tolerance = 0.0;  // exact goals keep the reachability oracle exact
    o.time_budget = 20.0;
    o.max_samples = 2000;
    o.seed = static_cast<std::uint32_t>(world + 1);
    o.algorithm = algorithms[world % 3];
    const Costmap extent(g, o.costmap);
    const Oracle oracle = testing::brute_force_costmap(g, extent, o.costmap);
    for (int query = 0; query < 4; ++query) {
      const Point2 s = random_free_position(oracle, rng);
      const Point2 t = random_free_position(oracle, rng);
      const PlanResult r = plan(g, slam::Pose2{s.x, s.y, 0.0}, t.x, t.y, o);
      const bool reachable = oracle_reachable(oracle, extent.cell_at(s), extent.cell_at(t));
      SCOPED_TRACE(::testing::Message() << "world " << world << " query " << query << " " << to_string(o.algorithm)
                                        << ": " << r.message);
      EXPECT_EQ(r.guard_rejections, 0u);
      if (!reachable) {
        ++unreachable;
        EXPECT_EQ(r.status, PlanStatus::kNoPath);
        continue;
      }
      ASSERT_NE(r.status, PlanStatus::kStartBlocked);
      ASSERT_NE(r.status, PlanStatus::kGoalBlocked);
      if (!r.solved()) continue;  // reachable but not found within 2000 samples: allowed
      ++solved;
      ASSERT_EQ(r.path.front(), s);
      ASSERT_EQ(r.path.back(), t);
      ASSERT_TRUE(oracle.path_free(r.path));
    }
  }
  RecordProperty("solved", solved);
  RecordProperty("unreachable", unreachable);
  // The property must not hold vacuously (measured: 98 solved, 20 unreachable of 120).
  EXPECT_GT(solved, 60);
  EXPECT_GT(unreachable, 5);
}

}  // namespace
}  // namespace lookahead::planner
