// SPDX-License-Identifier: MIT
#include "lookahead/planner/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "option_check.hpp"

namespace lookahead::planner {
namespace {

/// Closest point to p on segment a-b, and its distance.
Point2 closest_on_segment(Point2 a, Point2 b, Point2 p, double& dist) {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0.0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  const Point2 q{a.x + t * dx, a.y + t * dy};
  dist = distance(p, q);
  return q;
}

// How much path may lead out of the inflated band before it counts as blocked [m]: target
// selection looks this far for a free cell to start a plan from (nearest_free, 0.5 m).
constexpr double kMaxEscape = 0.5;

// The robot may stand inside the inflated band (pure pursuit cuts corners, the reactive
// stop leaves it close to a wall): a plan from there starts with a stretch through blocked
// cells back to free space. That stretch is the way out, not new walls on the path; it is
// dropped so only the rest is checked. Returns false when no point that passes comes within
// kMaxEscape of arc (the path really is blocked at its start).
template <typename PointOk>
bool drop_escape(const Costmap& costmap, Path& path, PointOk passes) {
  if (passes(path.front())) return true;
  const double step = 0.5 * costmap.resolution();
  double arc = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double len = distance(path[i], path[i + 1]);
    for (double t = step; t < len + step && arc + std::min(t, len) <= kMaxEscape; t += step) {
      const double u = std::min(t, len) / std::max(len, 1e-12);
      const Point2 p{path[i].x + u * (path[i + 1].x - path[i].x), path[i].y + u * (path[i + 1].y - path[i].y)};
      if (!passes(p)) continue;
      path.erase(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(i) + 1);
      path.insert(path.begin(), p);
      return true;
    }
    arc += len;
    if (arc > kMaxEscape) break;
  }
  return false;
}

}  // namespace

void validate(const FollowerOptions& o) {
  using detail::Bound;
  using detail::check_range;
  check_range("FollowerOptions.lookahead", o.lookahead, 0.0, 10.0, "m", Bound::kOpen);
  check_range("FollowerOptions.max_linear_speed", o.max_linear_speed, 0.0, 5.0, "m/s", Bound::kOpen);
  check_range("FollowerOptions.max_turn_rate", o.max_turn_rate, 0.0, 10.0, "rad/s", Bound::kOpen);
  check_range("FollowerOptions.rotate_in_place_angle", o.rotate_in_place_angle, 0.0, M_PI, "rad", Bound::kOpen);
  check_range("FollowerOptions.goal_tolerance", o.goal_tolerance, 0.0, 5.0, "m", Bound::kOpen);
  check_range("FollowerOptions.approach_gain", o.approach_gain, 0.0, 100.0, "1/s", Bound::kOpen);
}

PathFollower::PathFollower(Path path, const FollowerOptions& options)
    : path_(std::move(path)), options_((validate(options), options)) {
  if (path_.empty()) throw std::invalid_argument("PathFollower: the path has no waypoints");
  projection_ = path_.front();
}

void PathFollower::advance_projection(Point2 robot) {
  if (path_.size() < 2) return;
  // Search forward only, and only as far as the path could have been driven since the last
  // step (a few look-ahead lengths): a later part of the path passing close by is not a
  // shortcut the robot may take.
  const double horizon = 3.0 * options_.lookahead;
  double best = 0.0;
  Point2 best_point = closest_on_segment(path_[segment_], path_[segment_ + 1], robot, best);
  std::size_t best_segment = segment_;
  double arc = distance(projection_, path_[segment_ + 1]);
  for (std::size_t i = segment_ + 1; i + 1 < path_.size() && arc <= horizon; ++i) {
    double d = 0.0;
    const Point2 q = closest_on_segment(path_[i], path_[i + 1], robot, d);
    if (d < best) {
      best = d;
      best_point = q;
      best_segment = i;
    }
    arc += distance(path_[i], path_[i + 1]);
  }
  segment_ = best_segment;
  projection_ = best_point;
}

Point2 PathFollower::lookahead_point() const {
  double left = options_.lookahead;
  Point2 from = projection_;
  for (std::size_t i = segment_ + 1; i < path_.size(); ++i) {
    const double d = distance(from, path_[i]);
    if (d >= left) {
      const double t = left / d;
      return {from.x + t * (path_[i].x - from.x), from.y + t * (path_[i].y - from.y)};
    }
    left -= d;
    from = path_[i];
  }
  return path_.back();
}

VelocityCommand PathFollower::command(const slam::Pose2& pose) {
  const Point2 robot{pose.x, pose.y};
  const double to_goal = distance(robot, path_.back());
  if (goal_reached_ || to_goal <= options_.goal_tolerance) {
    goal_reached_ = true;
    return {};
  }
  advance_projection(robot);
  const Point2 target = lookahead_point();
  // The target in the robot frame (x forward, y left).
  const double dx = target.x - robot.x;
  const double dy = target.y - robot.y;
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  const double xr = c * dx + s * dy;
  const double yr = -s * dx + c * dy;
  const double heading_error = std::atan2(yr, xr);
  if (std::fabs(heading_error) > options_.rotate_in_place_angle) {
    return {0.0, std::copysign(options_.max_turn_rate, heading_error)};
  }
  const double l2 = xr * xr + yr * yr;
  const double curvature = l2 > 1e-12 ? 2.0 * yr / l2 : 0.0;  // Coulter Sec. 2: 2 y / L^2
  double v = std::min(options_.max_linear_speed, options_.approach_gain * to_goal);
  if (std::fabs(curvature * v) > options_.max_turn_rate) v = options_.max_turn_rate / std::fabs(curvature);
  return {v, curvature * v};
}

bool PathFollower::path_still_valid(const Costmap& costmap, Clearance clearance) const {
  if (goal_reached_) return true;
  Path remaining{projection_};
  remaining.insert(remaining.end(), path_.begin() + static_cast<std::ptrdiff_t>(segment_) + 1, path_.end());
  if (clearance == Clearance::kBody) {
    return drop_escape(costmap, remaining, [&](Point2 p) { return costmap.fits_body(p); }) &&
           costmap.path_fits_body(remaining);
  }
  return drop_escape(costmap, remaining, [&](Point2 p) { return costmap.is_free(p); }) &&
         costmap.path_is_free(remaining);
}

double PathFollower::remaining_length() const {
  if (segment_ + 1 >= path_.size()) return 0.0;
  double length = std::hypot(path_[segment_ + 1].x - projection_.x, path_[segment_ + 1].y - projection_.y);
  for (std::size_t i = segment_ + 1; i + 1 < path_.size(); ++i)
    length += std::hypot(path_[i + 1].x - path_[i].x, path_[i + 1].y - path_[i].y);
  return length;
}

}  // namespace lookahead::planner
