// SPDX-License-Identifier: MIT
// A feature map as one Gaussian: the vehicle pose and every feature's position stacked in
// one state, [x y theta | m1x m1y | m2x m2y | ...], with the full covariance. What a local
// front-end hands to the back-end at fusion (HybridSLAM sec. 2.2, 4).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::hybrid {

struct GaussianMap {
  Eigen::VectorXd mean;           ///< 3 + 2 K
  Eigen::MatrixXd covariance;     ///< (3 + 2 K)^2
  std::vector<long> ids;          ///< K feature identities (correspondence variables)
  std::vector<double> existence;  ///< K probabilities of existence

  [[nodiscard]] std::size_t features() const { return ids.size(); }
  [[nodiscard]] Pose2 vehicle() const;
  [[nodiscard]] Eigen::Vector2d feature(std::size_t k) const {
    return mean.segment<2>(3 + 2 * static_cast<Eigen::Index>(k));
  }
};

/// A vehicle pose estimate: mean and 3 x 3 covariance.
struct PoseGaussian {
  Pose2 mean;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

}  // namespace lookahead::slam::hybrid
