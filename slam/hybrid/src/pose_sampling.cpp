// SPDX-License-Identifier: MIT
#include "pose_sampling.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace lookahead::slam::hybrid {

Pose2 sample_motion(const Pose2& pose, const MotionStep& step, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Pose2& u = step.delta;
  return pose.compose(
      {u.x + step.sigma.x() * n(rng), u.y + step.sigma.y() * n(rng), u.theta + step.sigma.z() * n(rng)});
}

Pose2 sample_gaussian_pose(const Pose2& mean, const Matrix3& covariance, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Vector3 e(n(rng), n(rng), n(rng));
  // LDL^T with pivoting handles the semi-definite case; a negative pivot (round-off) is
  // clipped to zero.
  const Eigen::LDLT<Matrix3> ldlt(covariance);
  Vector3 d = ldlt.vectorD().cwiseMax(0.0).cwiseSqrt();
  Vector3 x = ldlt.transpositionsP().transpose() * (ldlt.matrixL() * d.cwiseProduct(e));
  return to_pose(to_vector(mean) + x);
}

}  // namespace lookahead::slam::hybrid
