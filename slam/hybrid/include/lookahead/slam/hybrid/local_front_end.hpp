// SPDX-License-Identifier: MIT
// The local mapper of the sub-mapping filter (HybridSLAM sec. 4, Fig. 1): it maps in the
// frame of the vehicle pose at the last fusion, starting with no uncertainty and no
// features, and converts its posterior to one Gaussian on demand. FastSLAM 2.0 (HYBRID) and
// an EKF (the paper's EKF baseline) implement it.
#pragma once

#include <vector>

#include "lookahead/slam/hybrid/gaussian_map.hpp"
#include "lookahead/slam/hybrid/motion_step.hpp"
#include "lookahead/slam/hybrid/range_bearing.hpp"

namespace lookahead::slam::hybrid {

class LocalFrontEnd {
 public:
  virtual ~LocalFrontEnd() = default;
  /// The control since the last call.
  virtual void predict(const MotionStep& step) = 0;
  /// The observations at the current pose (possibly none: still a time step).
  virtual void observe(const std::vector<RangeBearing>& observations) = 0;
  /// The vehicle pose in the local frame, as one Gaussian.
  [[nodiscard]] virtual PoseGaussian vehicle() const = 0;
  /// The local map as one Gaussian over the vehicle and the features whose probability of
  /// existence exceeds `min_existence`.
  [[nodiscard]] virtual GaussianMap to_gaussian(double min_existence) = 0;
  /// A new local map at the vehicle: origin here, no uncertainty, no features.
  virtual void restart() = 0;
};

}  // namespace lookahead::slam::hybrid
