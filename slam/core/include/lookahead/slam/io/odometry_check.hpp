// SPDX-License-Identifier: MIT
// What a log's odometry and clock may do before a filter sees them. Every reader passes its
// scans through check_odometry(), so the RBPF, SegSLAM (2D) and HybridSLAM, which all take a
// LaserLog, get the same treatment:
//  - a scan whose odometry pose or time stamp is not finite is skipped (it cannot be placed);
//  - a scan stamped before the last kept one is counted and kept in log order (the filters
//    step by odometry; dropping it would lose real data);
//  - an odometry step longer than LogReadOptions::max_odometry_step is a jump (a reset or
//    wrapped-around odometer, a robot carried elsewhere): the motion model is reset there,
//    i.e. the step counts as no motion and the odometry after it is re-anchored to the pose
//    before it, so the scan matcher places the robot from what it sees. Without this the
//    motion model would move every particle by kilometres and the map with it.
// Each event is counted and its first one kept as a message naming file:line; check_log()
// (log_check.hpp) reports them.
#pragma once

#include <cstddef>
#include <string>

#include "lookahead/slam/io/laser_log.hpp"

namespace lookahead::slam {

/// Applies the rules above to `log` in place (its options come from `options`).
void check_odometry(LaserLog& log, const LogReadOptions& options);

}  // namespace lookahead::slam
