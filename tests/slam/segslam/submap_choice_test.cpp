// SPDX-License-Identifier: MIT
#include "submap_choice.hpp"

#include <gtest/gtest.h>

#include "segmentation.hpp"

namespace lookahead::slam::segslam {
namespace {

// Eq. 3 with eq. 18 weights: the draws follow the weights, the null choice included.
TEST(SubmapChoice, DrawsFollowTheWeights) {
  MatchingOptions o;
  const double null_w = null_match_weight(o);
  const std::vector<double> w{null_w, 2 * null_w};  // null : m0 : m1 = 1 : 1 : 2
  std::mt19937_64 rng(7);
  int same = 0, m0 = 0, m1 = 0;
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    const ChoiceDraw d = draw_submap_choice(false, w, o, rng);
    if (d.choice == SubmapChoice::kSame) ++same;
    if (d.choice == SubmapChoice::kMatch) (d.match == 0 ? m0 : m1)++;
    ASSERT_NE(d.choice, SubmapChoice::kNew);
  }
  EXPECT_NEAR(same / double(n), 0.25, 0.01);
  EXPECT_NEAR(m0 / double(n), 0.25, 0.01);
  EXPECT_NEAR(m1 / double(n), 0.50, 0.01);
}

TEST(SubmapChoice, SegmentationMakesTheNullChoiceNew) {
  MatchingOptions o;
  std::mt19937_64 rng(1);
  EXPECT_EQ(draw_submap_choice(true, {}, o, rng).choice, SubmapChoice::kNew);
  EXPECT_EQ(draw_submap_choice(false, {}, o, rng).choice, SubmapChoice::kSame);
}

// Eq. 18: a tighter fit and a smaller correction both weigh more.
TEST(SubmapChoice, MatchWeightPrefersSmallErrorAndSmallTransforms) {
  MatchingOptions o;
  EXPECT_GT(match_weight(0.02, 0.5, o), match_weight(0.08, 0.5, o));
  EXPECT_GT(match_weight(0.05, 0.2, o), match_weight(0.05, 2.0, o));
  EXPECT_DOUBLE_EQ(null_match_weight(o), match_weight(o.null_error, 0.0, o));
}

// Eq. 13-14 and sec. 4.3: hard turns add more error than straight driving; the minimum
// segment size holds every criterion back; a predictive-score drop segments.
TEST(Segmentation, CriterionOnConstructedMotionErrors) {
  SegmentationOptions o;
  o.predictive_threshold = 0.5;  // the paper's value; off in the 2D defaults
  const double straight = motion_error_increment({0.5, 0, 0}, o);
  const double turn = motion_error_increment({0.1, 0, 1.2}, o);
  EXPECT_GT(turn, straight);
  double error = 0;
  int updates = 0;
  while (!should_segment(updates, error, -1.0, o)) {
    error += straight;
    ++updates;
    ASSERT_LT(updates, 10000);
  }
  EXPECT_GE(error, o.max_motion_error);  // segmented by motion error, at the threshold
  EXPECT_LT(error - straight, o.max_motion_error);
  EXPECT_FALSE(should_segment(o.min_segment_updates - 1, 10 * o.max_motion_error, 0.0, o));
  EXPECT_TRUE(should_segment(o.min_segment_updates, 0.0, o.predictive_threshold / 2, o));
  EXPECT_FALSE(should_segment(o.min_segment_updates, 0.0, (1 + o.predictive_threshold) / 2, o));
  o.predictive_threshold = 0.0;  // eq. 17 off: no score segments
  EXPECT_FALSE(should_segment(o.min_segment_updates, 0.0, 0.0, o));
}

}  // namespace
}  // namespace lookahead::slam::segslam
