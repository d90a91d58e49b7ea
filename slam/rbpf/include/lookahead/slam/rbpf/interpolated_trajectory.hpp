// SPDX-License-Identifier: MIT
// A filter's pose at every scan from its poses at the update scans. The filter estimates a
// pose where it updates (Grisetti et al. 2007 sec. IV: after a minimum travel) and, between
// updates, where a scan matcher placed a scan on the way. Those poses are kept as they are:
// each is an estimate of its own. The scans no estimate placed (no match) lie on the
// odometry's path, bent so that it starts on the estimate before them and ends on the one
// after. Odometry errs mostly in proportion to the distance and the turn travelled, so the
// correction is spread along the gap in that proportion.
#pragma once
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

/// The motion from update scan `a` to a scan `s` (a <= s) before the next update: the
/// matcher's estimate where `placed(s)`, else the odometry chained on from the scan before.
using MotionSinceUpdate = std::function<Pose2(std::size_t a, std::size_t s)>;
/// Whether scan `s` between two updates has a pose of its own (a scan matched on the way).
using PlacedBetweenUpdates = std::function<bool(std::size_t s)>;

/// Poses at scans 0..odometry.size()-1. `updates` are (scan index, pose) in scan order;
/// `motion` and `placed` describe the scans between updates; a radian of turn counts as
/// `metres_per_radian` metres of travel. Scans after the last update follow `motion`. Empty
/// when there is no update.
std::vector<Pose2> interpolate_between_updates(const std::vector<std::pair<std::size_t, Pose2>>& updates,
                                               const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion,
                                               const PlacedBetweenUpdates& placed, double metres_per_radian);

}  // namespace lookahead::slam
