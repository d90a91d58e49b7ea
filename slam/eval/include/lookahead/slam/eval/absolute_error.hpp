// SPDX-License-Identifier: MIT
// Absolute trajectory error after the best SE(2) alignment of the estimate onto a reference
// (closed-form least squares, Umeyama 1991 restricted to the plane without scale).
#pragma once

#include <vector>

#include "lookahead/slam/io/trajectory_io.hpp"

namespace lookahead::slam {

struct AbsoluteError {
  double rmse = 0.0;  ///< root mean square position error after alignment [m]
  double mean = 0.0;  ///< mean position error after alignment [m]
  double max = 0.0;   ///< [m]
  std::size_t matched = 0;
  Pose2 alignment;  ///< estimate frame -> reference frame
};

/// Pairs poses whose stamps are within `tolerance` seconds, then aligns and scores them.
AbsoluteError absolute_trajectory_error(const std::vector<StampedPose>& reference,
                                        const std::vector<StampedPose>& estimate, double tolerance = 0.005);

}  // namespace lookahead::slam
