// SPDX-License-Identifier: MIT
// The wide re-entry search of SegSLAM 3D (wide_reentry.hpp): its reach, the distinct peaks of
// the coarse search, and the acceptance that needs exactly one fitting pose.
#include "lookahead/slam/segslam/wide_reentry.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "candidate_reach.hpp"
#include "garage_drive.hpp"
#include "lookahead/slam/octree/ray_insertion.hpp"
#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam::segslam {
namespace {

using test_data::garage_log;
using test_data::map_of;
using test_data::window_of;

// `map` with a second copy of every voxel `shift_voxels` voxels along x: the same place twice,
// as a garage repeats its bays.
EvidenceOctree twice(const EvidenceOctree& map, int shift_voxels) {
  EvidenceOctree out = map;
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    out.set_log_odds({static_cast<std::uint16_t>(k.x + shift_voxels), k.y, k.z}, l);
  });
  return out;
}

bool at(const WindowMatch3& m, const Pose4& truth) {
  return (m.pose.position() - truth.position()).norm() < 0.15 &&
         std::abs(normalize_angle(m.pose.yaw - truth.yaw)) < 0.03;
}

// The reach is eq. 18's sigma_tau times `sigmas`, only where it exceeds the capped search.
TEST(WideReentry, ReachIsSizedBySigmaTauBeyondTheCapOnly) {
  const MatchingOptions o = segslam3d_defaults().matching;  // search 2 m / 0.4 rad, proximity 4 m, sigma 1.5 m
  const WideReentryOptions w;  // to 3 sigmas when 2 exceed the cap, cap 25 m, 0.1 rad/m up to 1 rad
  EXPECT_FALSE(wide_reach(o, 0.0, 6.0, w).has_value());  // 2 sigmas 3 m: the capped search covers it
  EXPECT_FALSE(wide_reach(o, 2.5, 6.0, w).has_value());  // 2 hypot(1.5, 2.5) = 5.8 m (3 sigmas 8.7 m)
  EXPECT_TRUE(wide_reach(o, 2.5, 5.0, w).has_value());   // ... unless the cap is lower
  EXPECT_TRUE(wide_reach(o, 2.7, 6.0, w).has_value());   // 6.2 m
  const auto m = wide_reach(o, 8.0, 6.0, w);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->search_radius, 3 * std::hypot(1.5, 8.0), 1e-12);
  EXPECT_NEAR(m->translation_sigma, candidate_reach(o, 8.0, 6.0).translation_sigma, 1e-12);
  EXPECT_NEAR(m->search_angle, std::hypot(0.4, 0.8), 1e-12);
  EXPECT_NEAR(m->proximity_radius, 4.0 + m->search_radius - 2.0, 1e-12);
  const auto capped = wide_reach(o, 100.0, 6.0, w);
  ASSERT_TRUE(capped.has_value());
  EXPECT_DOUBLE_EQ(capped->search_radius, 25.0);
  EXPECT_DOUBLE_EQ(capped->search_angle, 1.0);
  WideReentryOptions off;
  off.max_radius = 0;
  EXPECT_FALSE(wide_reach(o, 100.0, 6.0, off).has_value());
  WideReentryOptions one_peak;
  one_peak.peaks = 1;
  EXPECT_THROW(validate(one_peak), std::invalid_argument);
}

// A pending re-entry predicts the robot in the candidate's frame from its pose in its own
// submap, also after a segmentation started a fresh frame; a window's pose confirms it only
// within the tolerance.
TEST(WideReentry, PendingReentryPredictsThroughAFreshFrameAndIsConfirmedWithinTolerance) {
  const Pose4 pose{3.0, 1.0, 0.2, 0.3};     // the particle in its submap
  const Pose4 match{12.0, -4.0, 0.1, 1.2};  // where the wide stage put it in the candidate
  const Pose4 guess{10.0, -6.0, 0.0, 1.0};  // where the map sample did
  const PendingReentry p = pending_of(7, match, guess, pose);
  EXPECT_EQ(p.candidate, 7U);
  const Pose4 step{1.0, 0.1, 0.0, 0.05};  // the particle moves on in the same submap
  const Pose4 predicted = p.frame.compose(pose.compose(step));
  const Pose4 expected = match.compose(step);
  EXPECT_NEAR(predicted.x, expected.x, 1e-12);
  EXPECT_NEAR(predicted.y, expected.y, 1e-12);
  EXPECT_NEAR(normalize_angle(predicted.yaw - expected.yaw), 0.0, 1e-12);
  EXPECT_NEAR(p.guess_frame.compose(pose).x, guess.x, 1e-12);
  // A segmentation: the fresh frame starts at the particle's pose, where it is at the origin.
  const PendingReentry carried = carried_into(p, pose.compose(step));
  const Pose4 after = carried.frame.compose(step);  // one more step in the fresh frame
  const Pose4 truth = match.compose(step).compose(step);
  EXPECT_NEAR(after.x, truth.x, 1e-12);
  EXPECT_NEAR(after.y, truth.y, 1e-12);
  EXPECT_NEAR(normalize_angle(after.yaw - truth.yaw), 0.0, 1e-12);
  const WideReentryOptions w;                                              // 0.5 m, 0.08 rad
  EXPECT_TRUE(confirms(truth, truth.compose({0.3, -0.3, 0.4, 0.05}), w));  // height is not checked
  EXPECT_FALSE(confirms(truth, truth.compose({0.5, 0.3, 0.0, 0.0}), w));
  EXPECT_FALSE(confirms(truth, truth.compose({0.0, 0.0, 0.0, 0.1}), w));
}

// The peaks are the branch and bound's best first, then poses apart from every earlier one.
TEST(WideReentry, PeaksAreDistinctAndTheFirstIsTheBest) {
  const RangeLog3& log = garage_log();
  const MatchingOptions o = segslam3d_defaults().matching;
  const OctreeMatchTarget target = match_target_of(map_of(log, 5, 12), o);
  const SweepWindow w = window_of(log, 8, 11);
  const Pose4 guess = Pose4::level_of(*log.sweeps[8].truth).compose({3.0, -2.0, 0.0, 0.1});
  const LevelPoseGrid grid{4.0, 0.3, 0.2, 0.05};
  const auto peaks = level_search_peaks(target.field, w.scored, guess, grid, 4, 1.5, 0.15);
  ASSERT_EQ(peaks.size(), 4U);
  const LevelCoarseResult best = level_search_branch_and_bound(target.field, w.scored, guess, grid);
  EXPECT_EQ(peaks[0].score, best.score);
  EXPECT_NEAR(peaks[0].pose.x, best.pose.x, 1e-9);
  EXPECT_NEAR(peaks[0].pose.y, best.pose.y, 1e-9);
  for (std::size_t a = 0; a < peaks.size(); ++a) {
    if (a > 0) EXPECT_LE(peaks[a].score, peaks[a - 1].score);
    for (std::size_t b = 0; b < a; ++b) {
      const bool apart = std::hypot(peaks[a].pose.x - peaks[b].pose.x, peaks[a].pose.y - peaks[b].pose.y) > 1.5 ||
                         std::abs(normalize_angle(peaks[a].pose.yaw - peaks[b].pose.yaw)) > 0.15;
      EXPECT_TRUE(apart) << a << " vs " << b;
    }
  }
}

// A guess 12.2 m and 0.6 rad off (the single particle's at the garage loop's end was 8-26 m and
// 0.2-0.8 rad off) is beyond the capped +-6 m / 0.4 rad search, and within the wide one, which
// finds the true pose as the one pose that fits. Where the candidate holds the same place twice,
// 40 m apart, and the guess lies between them, each copy fits as well: the plain best pose of
// the wide search would be taken, the wide stage rejects the match as ambiguous.
TEST(WideReentry, AFarGuessIsMatchedWhenOnePoseFitsAndRejectedWhenTwoDo) {
  const RangeLog3& log = garage_log();
  const MatchingOptions base = segslam3d_defaults().matching;
  const EvidenceOctree once = map_of(log, 5, 12);
  const SweepWindow w = window_of(log, 8, 11);
  const Pose4 truth = Pose4::level_of(*log.sweeps[8].truth);
  const StructureTestOptions so;
  WideReentryOptions wide;
  const Pose4 guess{truth.x + 10.0, truth.y - 7.0, truth.z + 0.2, truth.yaw + 0.6};
  const OctreeMatchTarget single = match_target_of(once, base);
  EXPECT_FALSE(at(match_window(single, w, guess, candidate_reach(base, 8.0, 6.0), so), truth));
  const auto reach = wide_reach(base, 8.0, 6.0, wide);
  ASSERT_TRUE(reach.has_value());
  const WindowMatch3 found = match_window_unambiguous(single, w, guess, *reach, so, wide);
  EXPECT_TRUE(found.ok) << found.rejection << ", modes " << found.modes;
  EXPECT_TRUE(at(found, truth)) << truth.between(found.pose).x << ", " << truth.between(found.pose).y;
  EXPECT_EQ(found.modes, 1U);

  // The same place twice, 200 voxels (40 m) apart in x; the guess half way, at the true yaw.
  const OctreeMatchTarget doubled = match_target_of(twice(once, 200), base);
  const Pose4 between{truth.x + 20.0, truth.y, truth.z, truth.yaw};
  wide.max_radius = 21.0;
  const auto far = wide_reach(base, 11.0, 6.0, wide);  // 3 hypot(1.5, 11) = 33 m, capped at 21 m
  ASSERT_TRUE(far.has_value());
  MatchingOptions narrow_yaw = *far;
  narrow_yaw.search_angle = 0.1;  // the copies differ in x only; keeps the test quick
  const WindowMatch3 plain = match_window(doubled, w, between, narrow_yaw, so);
  const Pose4 copy{truth.x + 40.0, truth.y, truth.z, truth.yaw};
  ASSERT_TRUE(plain.ok && (at(plain, truth) || at(plain, copy))) << plain.rejection;  // either copy fits alone
  const WindowMatch3 ambiguous = match_window_unambiguous(doubled, w, between, narrow_yaw, so, wide);
  EXPECT_FALSE(ambiguous.ok);
  EXPECT_STREQ(ambiguous.rejection, "ambiguous");
  EXPECT_EQ(ambiguous.modes, 2U);
}

// The square that covers several particles' regions is centred on the first one's and
// reaches as far as the farthest edge of any, in x or y and in yaw.
TEST(WideReentry, CoveringRegionHoldsEveryRegion) {
  const WideRegion first{{10.0, 5.0, 1.0, 0.2}, 12.0, 0.6};
  const WideRegion east{{14.0, 6.0, 1.0, 0.4}, 10.0, 0.5};   // 4 m off in x: edge 14 m, yaw 0.7 rad
  const WideRegion south{{9.0, -1.5, 1.0, 0.1}, 13.0, 0.8};  // 6.5 m off in y: edge 19.5 m, yaw 0.9 rad
  const WideRegion one = covering_subgrid(first, {first});
  EXPECT_DOUBLE_EQ(one.radius, 12.0);
  EXPECT_DOUBLE_EQ(one.angle, 0.6);
  const WideRegion all = covering_subgrid(first, {first, east, south});
  EXPECT_DOUBLE_EQ(all.centre.x, 10.0);
  EXPECT_DOUBLE_EQ(all.radius, 19.5);
  EXPECT_NEAR(all.angle, 0.9, 1e-12);
  // Across the +-pi seam the yaw offset is the short way round.
  const WideRegion seam = covering_subgrid({{0, 0, 0, 3.1}, 5.0, 0.3}, {{{0, 0, 0, -3.1}, 5.0, 0.3}});
  EXPECT_NEAR(seam.angle, 0.3 + (2 * M_PI - 6.2), 1e-12);
}

// One search for several regions answers each from the peaks inside it: with the place twice
// (40 m apart), a region around either copy finds that copy alone, one spanning both is
// ambiguous, as three separate searches would decide.
TEST(WideReentry, RegionsSearchedTogetherAreEachAnsweredFromTheirOwnPeaks) {
  const RangeLog3& log = garage_log();
  const MatchingOptions base = segslam3d_defaults().matching;
  const SweepWindow w = window_of(log, 8, 11);
  const Pose4 truth = Pose4::level_of(*log.sweeps[8].truth);
  const Pose4 copy{truth.x + 40.0, truth.y, truth.z, truth.yaw};
  const OctreeMatchTarget doubled = match_target_of(twice(map_of(log, 5, 12), 200), base);
  WideReentryOptions wide;
  MatchingOptions o = *wide_reach(base, 8.0, 6.0, wide);
  o.search_angle = 0.1;  // the copies differ in x only; keeps the test quick
  const std::vector<WideRegion> regions{{{truth.x + 3.0, truth.y - 2.0, truth.z, truth.yaw}, 6.0, 0.1},
                                        {{copy.x - 3.0, copy.y + 2.0, copy.z, copy.yaw}, 6.0, 0.1},
                                        {{truth.x + 20.0, truth.y, truth.z, truth.yaw}, 21.0, 0.1}};
  const std::vector<WindowMatch3> found = match_regions_unambiguous(doubled, w, regions, o, {}, wide);
  ASSERT_EQ(found.size(), 3U);
  EXPECT_TRUE(found[0].ok && at(found[0], truth)) << found[0].rejection;
  EXPECT_TRUE(found[1].ok && at(found[1], copy)) << found[1].rejection;
  EXPECT_NEAR(found[1].translation, (copy.position() - regions[1].centre.position()).norm(),
              0.2);  // tau from its own centre
  EXPECT_FALSE(found[2].ok);
  EXPECT_STREQ(found[2].rejection, "ambiguous");
  // A single region is match_window_unambiguous.
  const WindowMatch3 alone = match_window_unambiguous(
      doubled, w, regions[0].centre,
      [&] {
        MatchingOptions r = o;
        r.search_radius = regions[0].radius;
        return r;
      }(),
      {}, wide);
  const WindowMatch3 one = match_regions_unambiguous(doubled, w, {regions[0]}, o, {}, wide).front();
  EXPECT_EQ(alone.ok, one.ok);
  EXPECT_EQ(alone.pose.x, one.pose.x);
  EXPECT_EQ(alone.weight, one.weight);
}

}  // namespace
}  // namespace lookahead::slam::segslam
