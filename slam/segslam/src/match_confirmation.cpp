// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/match_confirmation.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam::segslam {

PendingMatch pending_match(std::size_t segment, const Pose2& match, const Pose2& pose) {
  return {segment, match.compose(pose.inverse())};
}

PendingMatch carried_into(const PendingMatch& pending, const Pose2& origin) {
  return {pending.segment, pending.frame.compose(origin)};
}

bool confirms(const std::vector<PendingMatch>& pending, std::size_t segment, const Pose2& match, const Pose2& pose,
              double distance, double angle) {
  // Compared where the robot is, not frame to frame: a frame's origin may lie tens of metres
  // away, and the 0.05-0.16 rad by which right matches' headings scatter between attempts on
  // MIT CSAIL move it metres there, the robot centimetres.
  return std::any_of(pending.begin(), pending.end(), [&](const PendingMatch& p) {
    if (p.segment != segment) return false;
    const Pose2 predicted = p.frame.compose(pose);
    return std::hypot(predicted.x - match.x, predicted.y - match.y) <= distance &&
           std::abs(normalize_angle(predicted.theta - match.theta)) <= angle;
  });
}

}  // namespace lookahead::slam::segslam
