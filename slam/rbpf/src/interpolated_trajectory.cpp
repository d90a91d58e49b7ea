// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/interpolated_trajectory.hpp"

#include <cmath>

namespace lookahead::slam {
namespace {

// Travel from scan p to every scan up to q along the odometry, a turn weighted as metres.
std::vector<double> travel_along(const std::vector<Pose2>& odometry, std::size_t p, std::size_t q,
                                 double metres_per_radian) {
  std::vector<double> travel(q - p + 1, 0.0);
  for (std::size_t s = p + 1; s <= q; ++s) {
    const Pose2 step = odometry[s - 1].between(odometry[s]);
    travel[s - p] = travel[s - p - 1] + step.norm() + metres_per_radian * std::abs(step.theta);
  }
  return travel;
}

// The scans strictly between two estimates, at p and q, none of them placed: the odometry's
// path from p (`motion_p`, `motion_q` and motion(a, s) are motions from the update a before
// them), with the share of the correction (the estimated motion p -> q minus the odometry's,
// in p's frame) travelled so far.
struct Gap {
  std::size_t p, q;
  Pose2 pose_p, pose_q;      // the two estimates
  Pose2 motion_p, motion_q;  // motion(a, p) and the odometry's motion(a, q)
};

void fill_gap(const Gap& g, const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion, std::size_t a,
              double metres_per_radian, std::vector<Pose2>& out) {
  if (g.q <= g.p + 1) return;
  const Pose2 odometry_pq = g.motion_p.between(g.motion_q);
  const Pose2 estimated_pq = g.pose_p.between(g.pose_q);
  const Pose2 correction{estimated_pq.x - odometry_pq.x, estimated_pq.y - odometry_pq.y,
                         normalize_angle(estimated_pq.theta - odometry_pq.theta)};
  const std::vector<double> travel = travel_along(odometry, g.p, g.q, metres_per_radian);
  for (std::size_t s = g.p + 1; s < g.q; ++s) {
    const double f = travel.back() > 0 ? travel[s - g.p] / travel.back()
                                       : static_cast<double>(s - g.p) / static_cast<double>(g.q - g.p);
    const Pose2 odometry_ps = g.motion_p.between(motion(a, s));
    out[s] = g.pose_p.compose(
        {odometry_ps.x + f * correction.x, odometry_ps.y + f * correction.y, odometry_ps.theta + f * correction.theta});
  }
}

// The scans a..b-1 between two updates: placed scans keep their estimate, the gaps between
// estimates follow the odometry bent onto them.
void fill_interval(const std::pair<std::size_t, Pose2>& from, const std::pair<std::size_t, Pose2>& to,
                   const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion,
                   const PlacedBetweenUpdates& placed, double metres_per_radian, std::vector<Pose2>& out) {
  const auto [a, pose_a] = from;
  const auto [b, pose_b] = to;
  out[a] = pose_a;
  Gap g{a, a, pose_a, pose_a, motion(a, a), motion(a, a)};
  for (std::size_t s = a + 1; s < b; ++s) {
    if (!placed(s)) continue;
    g.q = s;
    g.motion_q = motion(a, s - 1).compose(odometry[s - 1].between(odometry[s]));
    g.pose_q = pose_a.compose(motion(a, s));
    fill_gap(g, odometry, motion, a, metres_per_radian, out);
    out[s] = g.pose_q;
    g = Gap{s, s, g.pose_q, g.pose_q, motion(a, s), motion(a, s)};
  }
  g.q = b;
  g.motion_q = motion(a, b - 1).compose(odometry[b - 1].between(odometry[b]));
  g.pose_q = pose_b;
  fill_gap(g, odometry, motion, a, metres_per_radian, out);
}

}  // namespace

std::vector<Pose2> interpolate_between_updates(const std::vector<std::pair<std::size_t, Pose2>>& updates,
                                               const std::vector<Pose2>& odometry, const MotionSinceUpdate& motion,
                                               const PlacedBetweenUpdates& placed, double metres_per_radian) {
  if (updates.empty()) return {};
  std::vector<Pose2> out(odometry.size());
  const auto& first = updates.front();
  for (std::size_t s = 0; s < first.first && s < odometry.size(); ++s) {
    out[s] = first.second.compose(odometry[first.first].between(odometry[s]));
  }
  for (std::size_t k = 0; k + 1 < updates.size(); ++k) {
    fill_interval(updates[k], updates[k + 1], odometry, motion, placed, metres_per_radian, out);
  }
  const auto& last = updates.back();
  for (std::size_t s = last.first; s < odometry.size(); ++s) {
    out[s] = last.second.compose(motion(last.first, s));
  }
  return out;
}

}  // namespace lookahead::slam
