// SPDX-License-Identifier: MIT
// Planar rigid-body pose (x, y, theta) with composition: the SE(2) algebra every part of
// lookahead shares (motion models, scan matching, relative-error evaluation).
#pragma once

#include <cmath>

namespace lookahead::slam {

/// Wraps an angle to (-pi, pi].
double normalize_angle(double a);

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  ///< [rad], kept in (-pi, pi] by the operations below

  /// this (+) other: `other` expressed in this pose's frame, brought to the world frame.
  [[nodiscard]] Pose2 compose(const Pose2& other) const;
  /// The pose whose composition with this one is the identity.
  [[nodiscard]] Pose2 inverse() const;
  /// this^-1 (+) other: `other` seen from this pose (the relative motion this -> other).
  [[nodiscard]] Pose2 between(const Pose2& other) const;
  [[nodiscard]] double norm() const { return std::hypot(x, y); }
};

}  // namespace lookahead::slam
