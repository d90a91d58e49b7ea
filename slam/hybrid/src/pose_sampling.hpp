// SPDX-License-Identifier: MIT
// Random draws of planar poses: through a noisy control step, and from a Gaussian whose
// covariance may be singular (a straight step has no heading noise in the paper's model).
#pragma once

#include <random>

#include "lookahead/slam/hybrid/motion_step.hpp"

namespace lookahead::slam::hybrid {

/// pose (+) (u + noise), noise ~ N(0, diag(sigma^2)).
Pose2 sample_motion(const Pose2& pose, const MotionStep& step, std::mt19937_64& rng);

/// A draw from N(mean, covariance); covariance positive semi-definite.
Pose2 sample_gaussian_pose(const Pose2& mean, const Matrix3& covariance, std::mt19937_64& rng);

}  // namespace lookahead::slam::hybrid
