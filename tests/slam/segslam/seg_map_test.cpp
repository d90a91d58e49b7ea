// SPDX-License-Identifier: MIT
// SegMap, local map samples and trajectory reconstruction (eq. 11-12) on hand-built submaps.
#include "lookahead/slam/segslam/seg_map.hpp"

#include <gtest/gtest.h>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {
namespace {

struct NoMap {};  // the graph code needs no map
using S = Submap<NoMap, Pose2>;
using M = SegMap<NoMap, Pose2>;

S submap(std::size_t first, std::size_t last, Pose2 entry, Pose2 exit, std::size_t pred = kNoSubmap,
         std::size_t parent = kNoSubmap) {
  S s;
  s.interval = {first, last, double(first), double(last)};
  s.entry = entry;
  s.exit = exit;
  s.predecessor = pred;
  s.parent = parent;
  s.path = {{first, entry}, {last, exit}};
  return s;
}

void expect_pose(const Pose2& a, const Pose2& b) {
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(normalize_angle(a.theta - b.theta), 0.0, 1e-9);
}

// Eq. 11: a drive of 2 m east, a left turn, 1 m north, in three frames.
TEST(TrajectoryReconstruction, ComposesExitAndEntryTransforms) {
  M m;
  const std::size_t a = m.add(submap(0, 10, {0, 0, 0}, {2, 0, M_PI / 2}));
  const std::size_t b = m.add(submap(10, 20, {}, {1, 0, 0}, a));  // fresh frame: entry = identity
  S c = submap(20, 30, {}, {0.5, 0, 0}, b);
  const auto chain = temporal_chain(m, c);
  ASSERT_EQ(chain.size(), 3u);
  const auto frames = chain_frames(chain);
  expect_pose(frames[1], {2, 0, M_PI / 2});
  expect_pose(frames[2], {2, 1, M_PI / 2});
  const auto traj = reconstruct_trajectory(chain, frames);
  ASSERT_EQ(traj.size(), 4u);  // switch scans are kept once
  expect_pose(traj.back().second, {2, 1.5, M_PI / 2});
}

// A match child re-enters its parent's frame: the loop closes there instead of carrying the
// drift of the eq. 11 chain.
TEST(TrajectoryReconstruction, MatchTakesTheParentsFrame) {
  M m;
  const std::size_t a = m.add(submap(0, 10, {0, 0, 0}, {5, 0, 0}));
  const std::size_t b = m.add(submap(10, 20, {}, {0.3, 0.2, 0.1}, a));  // drifted return
  S c = submap(20, 30, {0.1, 0.0, 0.0}, {0.2, 0, 0}, b, a);             // matched into a at (0.1, 0)
  const auto chain = temporal_chain(m, c);
  const auto frames = chain_frames_with_matches(m, chain);
  expect_pose(frames[2], frames[0]);
  expect_pose(frames[2].compose(c.exit), {0.2, 0, 0});
  EXPECT_NE(chain_frames(chain)[2].x, frames[2].x);  // plain eq. 11 would not close it
}

TEST(SegMap, GroupsSegmentsAndPrunesNonViableOnes) {
  M m;
  const std::size_t a = m.add(submap(0, 10, {}, {1, 0, 0}));
  const std::size_t a2 = m.add(submap(0, 10, {}, {1.1, 0, 0}));  // same interval: same segment
  const std::size_t b = m.add(submap(10, 20, {}, {1, 0, 0}, a));
  const std::size_t dead = m.add(submap(10, 15, {}, {1, 0, 0}, a2));
  EXPECT_EQ(m.segment_of(a).size(), 2u);
  EXPECT_EQ(m.segment_count(), 3u);
  EXPECT_EQ(m.prune({b}), 1u);  // the live particle descends from b: a2 stays (segment of a)
  EXPECT_FALSE(m.contains(dead));
  EXPECT_TRUE(m.contains(a2));
}

TEST(MapSampler, OneMemberPerSegmentPlacedByTheTransforms) {
  M m;
  const std::size_t a = m.add(submap(0, 10, {}, {2, 0, 0}));
  m.add(submap(0, 10, {}, {2, 0, 0}));  // a second member of a's segment, same exit
  const std::size_t b = m.add(submap(10, 20, {}, {0, 3, 0}, a));
  S open = submap(20, 30, {}, {1, 0, 0}, b);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 20; ++i) {
    const auto sample = sample_local_map(m, open, kNoSubmap, 100, rng);
    ASSERT_EQ(sample.size(), 3u);  // open, b, one of a's segment
    expect_pose(sample[1].frame, Pose2{0, -3, 0});
    expect_pose(sample[2].frame, Pose2{-2, -3, 0});
  }
}

TEST(MapSampler, SkipsTemporallyIncompatibleSegments) {
  M m;
  const std::size_t a = m.add(submap(0, 10, {}, {1, 0, 0}));
  const std::size_t b = m.add(submap(10, 20, {}, {1, 0, 0}, a));
  m.add(submap(5, 15, {}, {1, 0, 0}, kNoSubmap, b));  // overlaps both: never with them
  S open = submap(20, 30, {}, {1, 0, 0}, b);
  std::mt19937_64 rng(2);
  const auto sample = sample_local_map(m, open, kNoSubmap, 100, rng);
  EXPECT_EQ(sample.size(), 3u);
}

}  // namespace
}  // namespace lookahead::slam::segslam

namespace lookahead::slam::segslam {
namespace {

// Copies of one segment share a search (SegSlam3dExtras::share_by_segment) only when they are
// the same stretch in the same frame: the same interval along the same parent chain.
TEST(SegMapFirstCopy, SameIntervalAndParentChainOnly) {
  M m;
  const std::size_t a0 = m.add(submap(0, 10, {}, {1, 0, 0}));
  const std::size_t a1 = m.add(submap(0, 10, {}, {1.1, 0, 0}));         // another particle's copy
  const std::size_t b0 = m.add(submap(10, 20, {}, {1, 0, 0}, a0));      // fresh, after a0
  const std::size_t b1 = m.add(submap(10, 20, {}, {1, 0, 0}, a1));      // fresh, after a1
  const std::size_t c0 = m.add(submap(10, 20, {}, {1, 0, 0}, a0, a0));  // re-entered a0
  const std::size_t c1 = m.add(submap(10, 20, {}, {1, 0, 0}, a1, a1));  // re-entered a0's copy
  const std::size_t d = m.add(submap(10, 21, {}, {1, 0, 0}, a1));       // another interval
  EXPECT_EQ(m.first_copy(a0), a0);
  EXPECT_EQ(m.first_copy(a1), a0);
  EXPECT_EQ(m.first_copy(b1), b0);  // predecessors may differ: the frame starts at the robot
  EXPECT_EQ(m.first_copy(c0), c0);  // a match child is not a copy of a fresh submap
  EXPECT_EQ(m.first_copy(c1), c0);  // parents a0 and a1 have one interval
  EXPECT_EQ(m.first_copy(d), d);
}

TEST(SegMapFirstCopy, SkipsMergedCopies) {
  M m;
  const std::size_t r = m.add(submap(0, 10, {}, {1, 0, 0}));
  const std::size_t x0 = m.add(submap(10, 20, {}, {1, 0, 0}, r, r));  // two re-entries of r
  const std::size_t x1 = m.add(submap(10, 20, {}, {1, 0, 0}, r, r));
  EXPECT_EQ(m.first_copy(x1), x0);
  ASSERT_TRUE(m.merge_into_parent(x0, [](NoMap&, const NoMap&) {}));  // x0's map went into r
  EXPECT_EQ(m.first_copy(x1), x1);
}

}  // namespace
}  // namespace lookahead::slam::segslam
