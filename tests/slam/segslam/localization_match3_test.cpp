// SPDX-License-Identifier: MIT
// Eq. 19 in 3D: the localisation particle filter that matches a look-ahead window to a
// candidate submap (localization_match3.hpp), on the simulated garage drive.
#include "localization_match3.hpp"

#include <gtest/gtest.h>

#include <cstdio>

#include "garage_drive.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

using test_data::aisle_back_and_forth;
using test_data::garage_log;
using test_data::map_of;
using test_data::window_of;

struct Localization3Case {
  EvidenceOctree candidate = map_of(garage_log(), 5, 12);
  MatchingOptions options = segslam3d_defaults().matching;
  OctreeMatchTarget target = match_target_of(candidate, options);
  SweepWindow window = window_of(garage_log(), 8, 11);
  Pose4 truth = Pose4::level_of(*garage_log().sweeps[8].truth);

  [[nodiscard]] WindowMatch3 localize(const Pose4& guess, std::uint64_t seed) const {
    return localize_window3(candidate, target, window, guess, options, OctreeLikelihoodOptions{}, {}, seed);
  }
};

// From a guess 0.7 m and 0.08 rad off (inside the capped search's 2 m reach) the cloud
// converges on the true pose, as near as ICP gets from there, and tight enough that
// p(|Sigma_X|) keeps most of the weight.
TEST(LocalizationMatch3, ConvergesOnTheTruePoseFromAGuessWithinTheReach) {
  const Localization3Case c;
  const Pose4 guess = c.truth.compose({0.5, -0.5, 0.1, 0.08});
  const WindowMatch3 icp = match_window(c.target, c.window, guess, c.options);
  ASSERT_TRUE(icp.ok);
  for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    const WindowMatch3 m = c.localize(guess, seed);
    ASSERT_TRUE(m.ok) << "seed " << seed << ": " << m.rejection;
    EXPECT_LT((m.pose.position() - c.truth.position()).norm(), 0.15) << seed;
    EXPECT_NEAR(normalize_angle(m.pose.yaw - c.truth.yaw), 0.0, 0.03) << seed;
    EXPECT_LT(m.icp_error, icp.icp_error + 0.01) << seed;
    EXPECT_GT(m.spread_factor, 0.5) << seed;
    EXPECT_LE(m.spread_factor, 1.0) << seed;
    EXPECT_NEAR(m.weight, m.spread_factor * match_weight(m.icp_error, m.translation, c.options), 1e-12);
    EXPECT_GT(m.weight, 0.5 * icp.weight) << seed;
  }
}

TEST(LocalizationMatch3, TheSameSeedGivesTheSameMatch) {
  const Localization3Case c;
  const Pose4 guess = c.truth.compose({0.5, -0.5, 0.1, 0.08});
  const WindowMatch3 a = c.localize(guess, 7), b = c.localize(guess, 7);
  EXPECT_EQ(a.pose.x, b.pose.x);
  EXPECT_EQ(a.pose.yaw, b.pose.yaw);
  EXPECT_EQ(a.weight, b.weight);
}

// A window of another place is not matched, or weighs less than the right place's; a cloud
// held 4.2 m along the aisle (half a column spacing; a reach too narrow to get back) ends on
// a wrong pose that the structure test rejects, as ICP's does.
TEST(LocalizationMatch3, AnotherPlaceOrAPriorTooFarOffGivesNoMatch) {
  Localization3Case c;
  const WindowMatch3 right = c.localize(c.truth, 1);
  ASSERT_TRUE(right.ok) << right.rejection;
  Localization3Case other;
  other.candidate = map_of(garage_log(), 0, 2);
  other.target = match_target_of(other.candidate, other.options);
  const WindowMatch3 far = other.localize(c.truth, 1);
  EXPECT_TRUE(!far.ok || far.weight < right.weight);
  c.options.search_radius = 0.2;
  c.options.search_angle = 0.02;
  const WindowMatch3 wrong = c.localize(c.truth.compose({4.2, 0, 0, 0}), 1);
  EXPECT_GT((wrong.pose.position() - c.truth.position()).norm(), 1.0);
  EXPECT_FALSE(wrong.ok) << "free share " << wrong.structure.free_ratio;
}

// The filter with matching.use_localization_filter: the legs that come back re-enter the
// first legs' submaps through the localisation filter's matches, and the robot stays
// localised; the same seed with ICP matching takes other matches (the option is used).
TEST(LocalizationMatch3, TheFilterReentersOldSubmapsThroughTheLocalisationFilter) {
  SegSlam3dOptions o = test_data::aisle_options(4);
  o.segslam.matching.use_localization_filter = true;
  SegSlam3d localised(o);
  test_data::run_filter(localised, aisle_back_and_forth());
  const SegSlam3dStatistics& st = localised.statistics();
  std::printf("%zu matches of %zu offered, %zu searches\n", st.matches, st.match_offers.size(), st.match_attempts);
  EXPECT_GT(st.matches, 0U);
  const Eigen::Vector3d truth = aisle_back_and_forth().sweeps.back().truth->translation();
  EXPECT_LT((localised.estimate().position() - truth).norm(), 1.0);
  o.segslam.matching.use_localization_filter = false;
  SegSlam3d icp(o);
  test_data::run_filter(icp, aisle_back_and_forth());
  bool differ = icp.statistics().match_offers.size() != st.match_offers.size();
  for (std::size_t i = 0; !differ && i < st.match_offers.size(); ++i) {
    differ = icp.statistics().match_offers[i].weight != st.match_offers[i].weight;
  }
  EXPECT_TRUE(differ);
}

}  // namespace
}  // namespace lookahead::slam::segslam
