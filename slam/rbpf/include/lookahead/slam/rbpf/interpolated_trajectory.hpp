// SPDX-License-Identifier: MIT
// A filter's pose at every scan from its poses at the update scans. The filter estimates a
// pose only where it updates (Grisetti et al. 2007 sec. IV: after a minimum travel); the scans
// between two updates lie on the odometry's path, bent so that it starts on the first update's
// pose and ends on the second's. Odometry errs mostly in proportion to the distance and the
// turn travelled, so the correction is spread along the interval in that proportion.
#pragma once
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

/// The motion from update scan `a` to a scan `s` (a <= s) before the next update.
using MotionSinceUpdate = std::function<Pose2(std::size_t a, std::size_t s)>;

/// Poses at scans 0..odometry.size()-1. `updates` are (scan index, pose) in scan order;
/// `motion` places the scans between updates (the odometry, or scans matched on the way);
/// a radian of turn counts as `metres_per_radian` metres of travel. Scans after the last
/// update follow `motion`. Empty when there is no update.
std::vector<Pose2> interpolate_between_updates(const std::vector<std::pair<std::size_t, Pose2>>& updates,
                                               const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion,
                                               double metres_per_radian);

}  // namespace lookahead::slam
