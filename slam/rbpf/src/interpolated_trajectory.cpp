// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/interpolated_trajectory.hpp"

#include <cmath>

namespace lookahead::slam {
namespace {

// Travel from scan a to every scan up to b along the odometry, a turn weighted as metres.
std::vector<double> travel_along(const std::vector<Pose2>& odometry, std::size_t a, std::size_t b,
                                 double metres_per_radian) {
  std::vector<double> travel(b - a + 1, 0.0);
  for (std::size_t s = a + 1; s <= b; ++s) {
    const Pose2 step = odometry[s - 1].between(odometry[s]);
    travel[s - a] = travel[s - a - 1] + step.norm() + metres_per_radian * std::abs(step.theta);
  }
  return travel;
}

// The scans a..b between two updates: the odometry's path from the pose at a, with the share
// of the correction (estimated motion minus odometry motion, in a's frame) travelled so far.
void fill_interval(const std::pair<std::size_t, Pose2>& from, const std::pair<std::size_t, Pose2>& to,
                   const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion, double metres_per_radian,
                   std::vector<Pose2>& out) {
  const auto [a, pose_a] = from;
  const std::size_t b = to.first;
  const Pose2 odometry_ab = motion(a, b - 1).compose(odometry[b - 1].between(odometry[b]));
  const Pose2 estimated_ab = pose_a.between(to.second);
  const Pose2 correction{estimated_ab.x - odometry_ab.x, estimated_ab.y - odometry_ab.y,
                         normalize_angle(estimated_ab.theta - odometry_ab.theta)};
  const std::vector<double> travel = travel_along(odometry, a, b, metres_per_radian);
  for (std::size_t s = a; s < b; ++s) {
    const double f =
        travel.back() > 0 ? travel[s - a] / travel.back() : static_cast<double>(s - a) / static_cast<double>(b - a);
    const Pose2 odometry_as = motion(a, s);
    out[s] = pose_a.compose(
        {odometry_as.x + f * correction.x, odometry_as.y + f * correction.y, odometry_as.theta + f * correction.theta});
  }
}

}  // namespace

std::vector<Pose2> interpolate_between_updates(const std::vector<std::pair<std::size_t, Pose2>>& updates,
                                               const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion,
                                               double metres_per_radian) {
  if (updates.empty()) return {};
  std::vector<Pose2> out(odometry.size());
  const auto& first = updates.front();
  for (std::size_t s = 0; s < first.first && s < odometry.size(); ++s) {
    out[s] = first.second.compose(odometry[first.first].between(odometry[s]));
  }
  for (std::size_t k = 0; k + 1 < updates.size(); ++k) {
    fill_interval(updates[k], updates[k + 1], odometry, motion, metres_per_radian, out);
  }
  const auto& last = updates.back();
  for (std::size_t s = last.first; s < odometry.size(); ++s) {
    out[s] = last.second.compose(motion(last.first, s));
  }
  return out;
}

}  // namespace lookahead::slam
