// SPDX-License-Identifier: MIT
// The EKF-SLAM global map of HybridSLAM (Brooks & Bailey, HybridSLAM sec. 4, after CLSF, Williams et
// al. 2002): the state holds v-, the global pose of the current local map's origin, and the
// global features. Fusing a local map (a Gaussian in the frame of v-):
//  1. augmentation by g(v-, x_L) with the Jacobians of g (the covariance of HybridSLAM sec. 4),
//  2. association of the new features with the old ones by joint compatibility (JCBB),
//  3. fusion of each pair by the zero-noise observation z_f = theta_1 - theta_2 = 0
//     (HybridSLAM eq. (10)) and removal of one of the two identical features,
//  4. the old origin is replaced by the new vehicle pose: the next local map's origin.
// With `fusion.relinearise` (beyond the paper) steps 1-3 still choose the pairs, and the
// map is then the Gauss-Newton solution over all local maps (map_joining.hpp).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/hybrid/gaussian_map.hpp"
#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/map_joining.hpp"

namespace lookahead::slam::hybrid {

struct FusionReport {
  int local_features = 0;  ///< features offered by the local map
  int associated = 0;      ///< of them, fused with a global feature
  /// Joint NIS of the fused pairs' differences (zero-noise, as fused): chi^2 with
  /// 2 * associated dof when both maps are consistent (a diagnostic).
  double fusion_nis = 0.0;
  bool search_truncated = false;
};

class GlobalMap {
 public:
  /// The first local map starts at `start`, known exactly.
  GlobalMap(const FusionOptions& options, const Pose2& start = {});

  FusionReport fuse(const GaussianMap& local);

  /// The vehicle's global pose from the local one: v- (+) v_L with both covariances
  /// propagated (the local and global maps are independent).
  [[nodiscard]] PoseGaussian compose(const PoseGaussian& local) const;

  [[nodiscard]] Pose2 origin() const;
  [[nodiscard]] std::size_t features() const { return static_cast<std::size_t>((mean_.size() - 3) / 2); }
  [[nodiscard]] Eigen::Vector2d feature(std::size_t k) const;
  [[nodiscard]] Eigen::Matrix2d feature_covariance(std::size_t k) const;
  [[nodiscard]] const Eigen::VectorXd& mean() const { return mean_; }
  [[nodiscard]] const Eigen::MatrixXd& covariance() const { return covariance_; }

  /// Steps 1 and 4 alone, exposed for tests: the state after augmentation by g.
  void augment(const GaussianMap& local);

 private:
  std::vector<int> associate(std::size_t first_new, std::size_t count, FusionReport& report) const;
  /// Returns the joint NIS of the pairs.
  double fuse_pairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs);
  void remove_states(std::vector<Eigen::Index> indices);
  void relinearise(const GaussianMap& local, const std::vector<int>& match, std::size_t old_features);

  FusionOptions options_;
  Eigen::VectorXd mean_;
  Eigen::MatrixXd covariance_;
  /// With `relinearise`: every local map so far, re-solved at each fusion; mean_ and
  /// covariance_ then hold its newest origin and features.
  MapJoining joining_;
};

/// g(v, x_L): the local state [v_L, m_1 ... m_K] expressed in the global frame, and its
/// Jacobians (d g / d v: (3 + 2K) x 3; d g / d x_L: square).
struct LocalToGlobal {
  Eigen::VectorXd value;
  Eigen::MatrixXd d_origin;
  Eigen::MatrixXd d_local;
};
LocalToGlobal local_to_global(const Pose2& origin, const Eigen::VectorXd& local);

}  // namespace lookahead::slam::hybrid
