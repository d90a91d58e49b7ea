// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/scan_matched_reference.hpp"

#include <gtest/gtest.h>

namespace lookahead::slam {
namespace {

LaserScan scan_with(double base, double logger_time, const Pose2& pose) {
  LaserScan s;
  for (int i = 0; i < 20; ++i) s.ranges.push_back(static_cast<float>(base + 0.1 * i));
  s.logger_timestamp = logger_time;
  s.odometry = pose;
  return s;
}

TEST(ScanMatchedReference, PairsCorrectedScansWithRawScansOfTheSameRanges) {
  LaserLog raw, corrected;
  for (int k = 0; k < 10; ++k) raw.scans.push_back(scan_with(1.0 + k, 100.0 + k, {double(k), 0.0, 0.0}));
  // Every third raw scan, rounded differently (+4 mm), with a corrected pose; one scan
  // that the raw log never saw.
  for (int k : {0, 3, 6, 9}) {
    LaserScan c = scan_with(1.0 + k + 0.004, 1.13e9, {10.0 + k, 5.0, 0.1});
    corrected.scans.push_back(c);
  }
  corrected.scans.insert(corrected.scans.begin() + 2, scan_with(50.0, 1.13e9, {0.0, 0.0, 0.0}));
  const ScanMatchedReference r = reference_by_matching_scans(corrected, raw, 0.01);
  ASSERT_EQ(r.poses.size(), 4u);
  EXPECT_EQ(r.unmatched, 1u);
  EXPECT_DOUBLE_EQ(r.poses[0].t, 100.0);
  EXPECT_DOUBLE_EQ(r.poses[1].t, 103.0);
  EXPECT_DOUBLE_EQ(r.poses[3].t, 109.0);
  EXPECT_DOUBLE_EQ(r.poses[2].pose.x, 16.0);  // the corrected pose, not the raw odometry
}

TEST(ScanMatchedReference, RangesBeyondTheToleranceAreNotPaired) {
  LaserLog raw, corrected;
  raw.scans.push_back(scan_with(1.0, 100.0, {}));
  corrected.scans.push_back(scan_with(1.02, 0.0, {}));
  EXPECT_TRUE(reference_by_matching_scans(corrected, raw, 0.01).poses.empty());
  EXPECT_EQ(reference_by_matching_scans(corrected, raw, 0.03).poses.size(), 1u);
}

}  // namespace
}  // namespace lookahead::slam
