// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/scan_matched_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lookahead::slam {
namespace {

double mean_range_difference(const LaserScan& a, const LaserScan& b) {
  const std::size_t n = std::min(a.ranges.size(), b.ranges.size());
  if (n == 0 || a.ranges.size() != b.ranges.size()) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += std::abs(static_cast<double>(a.ranges[i]) - b.ranges[i]);
  return sum / static_cast<double>(n);
}

}  // namespace

ScanMatchedReference reference_by_matching_scans(const LaserLog& corrected, const LaserLog& raw, double tolerance) {
  ScanMatchedReference out;
  std::size_t from = 0;
  for (const LaserScan& c : corrected.scans) {
    std::size_t found = raw.scans.size();
    for (std::size_t j = from; j < raw.scans.size(); ++j) {
      if (mean_range_difference(c, raw.scans[j]) <= tolerance) {
        found = j;
        break;
      }
    }
    if (found == raw.scans.size()) {
      ++out.unmatched;
      continue;
    }
    out.poses.push_back({raw.scans[found].logger_timestamp, c.odometry});
    from = found + 1;
  }
  return out;
}

}  // namespace lookahead::slam
