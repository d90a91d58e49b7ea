// SPDX-License-Identifier: MIT
// A FastSLAM particle with correspondence variables (HybridSLAM eq. (8)): a weight, a pose
// with no uncertainty, and per feature an EKF (mean, covariance), a probability of
// existence and gamma, the identity of the common feature it stands for.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::hybrid {

struct Landmark {
  Eigen::Vector2d mean;
  Eigen::Matrix2d covariance;
  double existence = 0.5;
  long id = -1;  ///< gamma: the common feature this one corresponds to
};

struct Particle {
  Pose2 pose;
  double weight = 1.0;  ///< normalised over the set
  std::vector<Landmark> landmarks;
};

/// What one particle did with one observation (the options it votes on, HybridSLAM sec. 3.1).
struct Decision {
  enum class Kind { kSpurious, kAssociated, kCreated };
  Kind kind = Kind::kSpurious;
  int landmark = -1;  ///< index in the particle's map (associated or created)
};

}  // namespace lookahead::slam::hybrid
