// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/odometry_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>
#include <vector>

namespace lookahead::slam {
namespace {

bool finite(const Pose2& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta); }

void note(LogEvent& event, const LaserLog& log, const LaserScan& scan, const std::string& what) {
  if (event.count++ == 0) event.first = fmt::format("{}:{}: {}", log.path, scan.source_line, what);
}

}  // namespace

void check_odometry(LaserLog& log, const LogReadOptions& options) {
  std::vector<LaserScan> kept;
  kept.reserve(log.scans.size());
  Pose2 correction;  // re-anchors the odometry after each jump: kept = correction (+) raw
  Pose2 last_raw;
  for (LaserScan& scan : log.scans) {
    if (!finite(scan.odometry) || !std::isfinite(scan.timestamp)) {
      note(log.non_finite, log, scan,
           fmt::format("odometry ({}, {}, {}) at t = {} is not finite; scan skipped", scan.odometry.x, scan.odometry.y,
                       scan.odometry.theta, scan.timestamp));
      continue;
    }
    // Kept in log order: real logs carry such stamps (the corrected Intel log 4, the FLIRT
    // Intel log 113) and the filters step by odometry, not by time.
    if (!kept.empty() && scan.timestamp < kept.back().timestamp) {
      note(log.time_reversals, log, scan,
           fmt::format("time {} is before the previous scan's {}; kept in log order", scan.timestamp,
                       kept.back().timestamp));
    }
    const Pose2 raw = scan.odometry;
    if (!kept.empty()) {
      const double step = last_raw.between(raw).norm();
      if (step > options.max_odometry_step) {
        note(log.odometry_jumps, log, scan,
             fmt::format("odometry jumps {:.1f} m (limit max_odometry_step = {} m); motion model reset", step,
                         options.max_odometry_step));
        correction = kept.back().odometry.compose(raw.inverse());
      }
    }
    last_raw = raw;
    scan.odometry = correction.compose(raw);
    kept.push_back(std::move(scan));
  }
  log.scans = std::move(kept);
}

}  // namespace lookahead::slam
