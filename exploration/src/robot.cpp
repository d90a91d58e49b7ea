// SPDX-License-Identifier: MIT
#include "lookahead/exploration/robot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lookahead/exploration/world_source.hpp"

namespace lookahead::exploration {
namespace {

void require(bool ok, const char* field, double value, const char* why) {
  if (!ok) {
    throw std::invalid_argument(std::string("RobotOptions.") + field + " = " + std::to_string(value) + ": " + why);
  }
}

}  // namespace

void RobotOptions::validate() const {
  require(radius > 0, "radius", radius, "must be > 0");
  require(max_speed > 0, "max_speed", max_speed, "must be > 0");
  require(max_turn_rate > 0, "max_turn_rate", max_turn_rate, "must be > 0");
  require(collision_step > 0, "collision_step", collision_step, "must be > 0");
}

bool disc_collides(const World& world, const Eigen::Vector2d& centre, double radius) {
  const slam::CellIndex lo = world.cell_of(centre - Eigen::Vector2d(radius, radius));
  const slam::CellIndex hi = world.cell_of(centre + Eigen::Vector2d(radius, radius));
  const double res = world.resolution();
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!world.is_occupied(slam::CellIndex{x, y})) continue;
      // Nearest point of the cell square to the centre.
      const Eigen::Vector2d c0 = world.origin() + res * Eigen::Vector2d(x, y);
      const Eigen::Vector2d nearest = centre.cwiseMax(c0).cwiseMin(c0 + Eigen::Vector2d(res, res));
      if ((nearest - centre).squaredNorm() < radius * radius) return true;
    }
  }
  return false;
}

slam::Pose2 integrate_arc(const slam::Pose2& p, double v, double omega, double dt) {
  const double dtheta = omega * dt;
  if (std::abs(dtheta) < 1e-9) {
    return {p.x + v * dt * std::cos(p.theta), p.y + v * dt * std::sin(p.theta),
            slam::normalize_angle(p.theta + dtheta)};
  }
  const double r = v / omega;  // signed turning radius
  return {p.x + r * (std::sin(p.theta + dtheta) - std::sin(p.theta)),
          p.y - r * (std::cos(p.theta + dtheta) - std::cos(p.theta)), slam::normalize_angle(p.theta + dtheta)};
}

Robot::Robot(const World& world, const slam::Pose2& start, const RobotOptions& options)
    : world_(&world), o_(options), pose_(start) {
  o_.validate();
  check_start(world, world.source(), start, o_.radius);
}

StepResult Robot::step(double v, double omega, double dt) {
  if (!(dt > 0)) throw std::invalid_argument("Robot::step: dt must be > 0");
  v = std::clamp(v, -o_.max_speed, o_.max_speed);
  omega = std::clamp(omega, -o_.max_turn_rate, o_.max_turn_rate);
  // Turning in place never moves the disc, so only the driven length needs sub-steps.
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(v) * dt / o_.collision_step)));
  StepResult result;
  const slam::Pose2 start = pose_;
  for (int k = 1; k <= pieces; ++k) {
    const double t = dt * k / pieces;
    const slam::Pose2 next = integrate_arc(start, v, omega, t);
    if (disc_collides(*world_, {next.x, next.y}, o_.radius)) {
      result.collided = true;
      break;
    }
    pose_ = next;
    result.distance = std::abs(v) * t;
    result.turned = omega * t;
  }
  result.pose = pose_;
  return result;
}

}  // namespace lookahead::exploration
