// SPDX-License-Identifier: MIT
// The global map as the joint least-squares estimate of every local map fused so far,
// re-linearised at each fusion (Gauss-Newton), after the iterated sparse local submap
// joining filter (Huang, Wang & Dissanayake, "Iterated SLSJF", 2008). Beyond HybridSLAM
// HybridSLAM sec. 4, which augments an EKF once per local map and never revisits the linearisation:
// see global_map.cpp for why.
//
// Variables: the origins v_1 ... v_K of the local maps after the first (v_0, the start, is
// known exactly) and the global features. Local map k is one Gaussian "observation" of
// [v_{k-1}^-1 (+) v_k, R(theta_{k-1})^T (f - t_{k-1}) for each of its features].
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::hybrid {

struct GaussianMap;

class MapJoining {
 public:
  explicit MapJoining(const Pose2& start);

  /// Adds local map `local` (in the frame of the newest origin) whose k-th feature is
  /// global feature `feature_of[k]`, or a new one when -1 (appended in order, starting at
  /// `new_feature_guess`). `pose_guess` and `new_feature_guess` (global) start the solver.
  void add(const GaussianMap& local, const std::vector<int>& feature_of, const Pose2& pose_guess,
           const std::vector<Eigen::Vector2d>& new_feature_guess);

  /// Gauss-Newton from the current estimate, at most `iterations` steps; returns the steps.
  int solve(int iterations);

  /// The newest origin and every feature, [x y theta | f1x f1y | ...], and their joint
  /// covariance (the inverse of the information at the solution, marginalised).
  void marginal(Eigen::VectorXd& mean, Eigen::MatrixXd& covariance) const;

  [[nodiscard]] std::size_t poses() const { return poses_.size(); }  ///< v_0 ... v_K
  [[nodiscard]] std::size_t features() const { return features_.size(); }
  [[nodiscard]] const Pose2& pose(std::size_t k) const { return poses_[k]; }
  [[nodiscard]] const Eigen::Vector2d& feature(std::size_t k) const { return features_[k]; }

 private:
  struct Factor {
    int from = 0;                 ///< origin pose index (0 = the start, fixed)
    std::vector<int> features;    ///< global feature per local feature
    Eigen::VectorXd mean;         ///< the local map, 3 + 2 K
    Eigen::MatrixXd information;  ///< its inverse covariance
  };
  [[nodiscard]] Eigen::Index pose_column(int pose) const { return 3 * static_cast<Eigen::Index>(pose - 1); }
  [[nodiscard]] Eigen::Index feature_column(int feature) const;
  [[nodiscard]] Eigen::Index columns() const;
  [[nodiscard]] Eigen::MatrixXd information(Eigen::VectorXd* gradient) const;
  void residual_and_jacobian(const Factor& f, Eigen::VectorXd& r, Eigen::MatrixXd& j,
                             std::vector<Eigen::Index>& cols) const;

  std::vector<Pose2> poses_;  ///< v_0 (fixed) ... v_K
  std::vector<Eigen::Vector2d> features_;
  std::vector<Factor> factors_;
};

}  // namespace lookahead::slam::hybrid
