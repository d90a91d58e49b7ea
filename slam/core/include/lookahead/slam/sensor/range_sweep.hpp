// SPDX-License-Identifier: MIT
// One 3D range sweep (a spinning 2D laser's half turn, or one 3D scan) and a log of them:
// what `lookahead slam3d` reads, whether simulated or from files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lookahead/slam/geometry/pose3.hpp"
#include "lookahead/slam/sensor/ray3.hpp"

namespace lookahead::slam {

struct RangeSweep {
  double time = 0.0;  ///< [s], at the sweep's end
  /// Dead-reckoned robot pose at the sweep's end (IMU roll and pitch, integrated yaw).
  Pose3 odometry = Pose3::Identity();
  /// Beams in the robot frame at the sweep's end. A sensor that moves during the sweep is
  /// de-skewed with dead reckoning, so each beam keeps its own origin.
  std::vector<Ray3> rays;
  std::optional<Pose3> truth;  ///< ground truth at the sweep's end, when simulated
};

struct RangeLog3 {
  std::string source;  ///< what produced it (a world name or a folder)
  std::vector<RangeSweep> sweeps;
  [[nodiscard]] bool has_truth() const { return !sweeps.empty() && sweeps.front().truth.has_value(); }
};

}  // namespace lookahead::slam
