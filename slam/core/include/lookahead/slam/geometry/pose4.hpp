// SPDX-License-Identifier: MIT
// A gravity-aligned 3D pose (x, y, z, yaw): the state of a 3D particle (rbpf3d: roll and
// pitch are the IMU's) and the transform between SegSLAM 3D submap frames, which are all
// level. Offers the algebra the generic SegSLAM graph code needs (compose, inverse,
// between; the default is the identity), as Pose2 does in 2D.
#pragma once

#include <cmath>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/geometry/pose3.hpp"

namespace lookahead::slam {

struct Pose4 {
  double x = 0.0, y = 0.0, z = 0.0;
  double yaw = 0.0;  ///< [rad], kept in (-pi, pi]

  /// this (+) other: `other` expressed in this pose's frame, brought to the world frame.
  [[nodiscard]] Pose4 compose(const Pose4& o) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {x + c * o.x - s * o.y, y + s * o.x + c * o.y, z + o.z, normalize_angle(yaw + o.yaw)};
  }
  [[nodiscard]] Pose4 inverse() const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {-c * x - s * y, s * x - c * y, -z, normalize_angle(-yaw)};
  }
  /// this^-1 (+) other: `other` seen from this pose.
  [[nodiscard]] Pose4 between(const Pose4& o) const { return inverse().compose(o); }
  [[nodiscard]] Eigen::Vector3d position() const { return {x, y, z}; }
  /// The planar part (x, y, yaw), e.g. for eq. 13-14 or a top-view picture.
  [[nodiscard]] Pose2 planar() const { return {x, y, yaw}; }

  /// The level part of a full pose: its position and yaw.
  static Pose4 level_of(const Pose3& p) {
    const Eigen::Vector3d t = p.translation();
    return {t.x(), t.y(), t.z(), euler_of(p.linear()).yaw};
  }
  /// The full pose with the given roll and pitch (R = Rz(yaw) Ry(pitch) Rx(roll)).
  [[nodiscard]] Pose3 with_tilt(double roll, double pitch) const { return make_pose3(position(), {roll, pitch, yaw}); }
  [[nodiscard]] Pose3 level_pose3() const { return with_tilt(0.0, 0.0); }
};

}  // namespace lookahead::slam
