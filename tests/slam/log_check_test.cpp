// SPDX-License-Identifier: MIT
// check_log() on a synthetic log: the gaps between scans it reports.
#include "lookahead/slam/io/log_check.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace lookahead::slam {
namespace {

// Scans every 0.5 s, with a 4 s pause before each scan in `pauses_before` (indices); the
// stamps are exact in binary, so the pauses are equal to the bit.
LaserLog log_with_pauses(const std::vector<std::size_t>& pauses_before) {
  LaserLog log;
  double t = 0.0;
  for (std::size_t i = 0; i < 200; ++i) {
    t += std::find(pauses_before.begin(), pauses_before.end(), i) != pauses_before.end() ? 4.0 : 0.5;
    LaserScan s;
    s.timestamp = t;
    s.ranges.assign(181, 3.0f);
    s.angle_min = -1.5708;
    s.angle_increment = 0.0174533;
    s.odometry = {0.01 * static_cast<double>(i), 0.0, 0.0};
    log.scans.push_back(s);
  }
  return log;
}

TEST(LogCheck, EqualGapsAreListedInTimeOrder) {
  const LogCheck c = check_log(log_with_pauses({150, 20, 90, 60}));
  ASSERT_EQ(c.largest_gaps.size(), 3u);
  EXPECT_EQ(c.long_gaps, 4u);
  EXPECT_EQ(c.largest_gaps[0].seconds, 4.0);
  EXPECT_LT(c.largest_gaps[0].t, c.largest_gaps[1].t);
  EXPECT_LT(c.largest_gaps[1].t, c.largest_gaps[2].t);
  EXPECT_EQ(c.largest_gaps[0].t, 20 * 0.5 + 4.0);      // scan 20: 20 periods, then its pause
  EXPECT_EQ(c.largest_gaps[2].t, 88 * 0.5 + 3 * 4.0);  // scan 90, after the pauses before 20, 60 and 90
}

}  // namespace
}  // namespace lookahead::slam
