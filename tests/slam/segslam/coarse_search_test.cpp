// SPDX-License-Identifier: MIT
// The coarse search that seeds matching: the near field's dilated levels against a brute
// force box test, and the branch and bound against the exhaustive search on constructed maps.
#include "lookahead/slam/segslam/coarse_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "../test_world.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::slam::segslam {
namespace {

// The test room mapped from a row of poses along its lower corridor.
OccupancyGrid room_map() {
  const auto world = test::room_world();
  OccupancyGrid map;
  for (double x = 1.5; x < 8.5; x += 0.5)
    insert_scan(map, {x, 1.0, 0}, test::simulate_scan(world, {x, 1.0, 0}, {}), {});
  return map;
}

// A few scattered obstacle cells: large flat regions and many equal scores (ties).
OccupancyGrid sparse_map(std::mt19937_64& rng) {
  OccupancyGrid map;
  std::uniform_int_distribution<int> cell(-60, 60);
  for (int k = 0; k < 25; ++k) map.add_log_odds({cell(rng), cell(rng)}, 3000);
  return map;
}

// The end points of a scan from `pose`, in the robot frame.
Points2 scan_points(const Pose2& pose, std::size_t every) {
  const LaserScan s = test::simulate_scan(test::room_world(), pose, {});
  Points2 out;
  for (std::size_t b = 0; b < s.ranges.size(); b += every) {
    if (!std::isfinite(s.ranges[b])) continue;
    out.emplace_back(s.ranges[b] * std::cos(s.bearing(b)), s.ranges[b] * std::sin(s.bearing(b)));
  }
  return out;
}

TEST(NearField, DilatedLevelsAreTheBoxTest) {
  std::mt19937_64 rng(5);
  const OccupancyGrid map = sparse_map(rng);
  const std::vector<int> widths{1, 2, 7, 70};
  const NearField field(map, GridTile::kFar - 1, widths);
  ASSERT_EQ(field.levels(), widths.size() + 1);
  const auto near = [&](int x, int y) { return map.dist2({x, y}) < GridTile::kFar; };
  std::uniform_int_distribution<int> cell(-160, 100);
  int near_seen = 0;
  for (int k = 0; k < 3000; ++k) {
    const int x = cell(rng), y = cell(rng);
    ASSERT_EQ(field.near(0, x, y), near(x, y)) << x << " " << y;
    for (std::size_t l = 0; l < widths.size(); ++l) {
      bool any = false;
      for (int dx = 0; dx < widths[l] && !any; ++dx) {
        for (int dy = 0; dy < widths[l] && !any; ++dy) any = near(x + dx, y + dy);
      }
      ASSERT_EQ(field.near(l + 1, x, y), any) << "level " << l + 1 << " at " << x << " " << y;
      near_seen += any;
    }
  }
  EXPECT_GT(near_seen, 100);  // the comparison saw both answers
  // A smaller distance: the cells within it, no more.
  const NearField close(map, 4);
  for (int k = 0; k < 3000; ++k) {
    const int x = cell(rng), y = cell(rng);
    ASSERT_EQ(close.near(0, x, y), map.dist2({x, y}) <= 4) << x << " " << y;
  }
}

// The branch and bound returns exactly the exhaustive search's pose and score (including
// which of equal scores), from guesses scattered around the true pose.
// `field_radius`: the field is built for a grid that wide (the 2D filter builds one per
// candidate for its widest reach and searches narrower grids on it).
void expect_same_optimum(const OccupancyGrid& map, const Points2& points, std::mt19937_64& rng, int trials,
                         double search_radius = 2.0, double field_radius = 2.0) {
  const PoseGrid grid{search_radius, 0.24, 0.25, 0.05};
  const PoseGrid field_grid{field_radius, grid.step, grid.angle, grid.angle_step};
  const NearField field(map, GridTile::kFar - 1, branch_and_bound_dilations(field_grid, map.resolution()));
  ASSERT_GE(field.levels(), branch_and_bound_dilations(grid, map.resolution()).size() + 1);
  std::uniform_real_distribution<double> off(-1.5, 1.5), turn(-0.3, 0.3);
  for (int t = 0; t < trials; ++t) {
    const Pose2 guess{4.0 + off(rng), 1.0 + off(rng), turn(rng)};
    const CoarseResult all = coarse_search_exhaustive(field, points, guess, grid);
    const CoarseResult bnb = coarse_search_branch_and_bound(field, points, guess, grid);
    ASSERT_EQ(bnb.score, all.score) << "trial " << t;
    ASSERT_EQ(bnb.pose.x, all.pose.x) << "trial " << t;
    ASSERT_EQ(bnb.pose.y, all.pose.y) << "trial " << t;
    ASSERT_EQ(bnb.pose.theta, all.pose.theta) << "trial " << t;
  }
}

TEST(CoarseSearch, BranchAndBoundFindsTheExhaustiveOptimumOnTheRoom) {
  std::mt19937_64 rng(11);
  expect_same_optimum(room_map(), scan_points({4.0, 1.0, 0.0}, 3), rng, 60);
}

TEST(CoarseSearch, AFieldBuiltForAWiderGridGivesTheSameOptimum) {
  std::mt19937_64 rng(13);
  const OccupancyGrid map = room_map();
  const double narrow = 0.3;  // a grid of 3 x 3 translations needs fewer levels than a 6 m one
  ASSERT_LT(branch_and_bound_dilations({narrow, 0.24, 0.25, 0.05}, map.resolution()).size(),
            branch_and_bound_dilations({6.0, 0.24, 0.25, 0.05}, map.resolution()).size());
  expect_same_optimum(map, scan_points({4.0, 1.0, 0.0}, 3), rng, 40, narrow, 6.0);
}

TEST(CoarseSearch, BranchAndBoundBreaksTiesAsTheExhaustiveSearch) {
  std::mt19937_64 rng(12);
  for (int m = 0; m < 5; ++m) expect_same_optimum(sparse_map(rng), scan_points({4.0, 1.0, 0.0}, 6), rng, 20);
}

TEST(CoarseSearch, FindsTheScanPoseFromAFarGuess) {
  const OccupancyGrid map = room_map();
  const PoseGrid grid{2.0, 0.24, 0.25, 0.05};
  const NearField field(map, GridTile::kFar - 1, branch_and_bound_dilations(grid, map.resolution()));
  const Pose2 truth{4.2, 1.1, 0.05};
  const CoarseResult r = coarse_search_branch_and_bound(field, scan_points(truth, 3), {5.1, 0.4, -0.1}, grid);
  EXPECT_NEAR(r.pose.x, truth.x, grid.step);
  EXPECT_NEAR(r.pose.y, truth.y, grid.step);
  EXPECT_NEAR(r.pose.theta, truth.theta, grid.angle_step);
}

TEST(CoarseSearch, BranchAndBoundNeedsTheGridsLevels) {
  const OccupancyGrid map = room_map();
  const NearField field(map, GridTile::kFar - 1, {3});
  EXPECT_THROW(coarse_search_branch_and_bound(field, scan_points({4, 1, 0}, 6), {4, 1, 0}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace lookahead::slam::segslam
