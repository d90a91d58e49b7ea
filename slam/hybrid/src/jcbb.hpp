// SPDX-License-Identifier: MIT
// Joint compatibility branch and bound (Neira & Tardos, IEEE T-RA 17(6), 2001), the
// association test of HybridSLAM sec. 4. Each item i (an observation, or a local feature
// at fusion) is paired with at most one target j (a mapped feature); a pairing set is
// jointly compatible when the stacked innovation passes a chi-square test under the joint
// covariance H P H^T + R. The search returns the compatible set with the most pairings
// (ties: the smallest joint NIS). Branch and bound on both: a branch that cannot exceed
// the best pairing count and already has a larger joint NIS is cut (exact, see jcbb.cpp).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace lookahead::slam::hybrid {

/// One individually compatible pairing: innovation nu (2) = z - h, its Jacobian H (2 x n)
/// w.r.t. the state of covariance P, and the item's noise R (zero at fusion).
struct PairingCandidate {
  int item = -1;
  int target = -1;
  Eigen::Vector2d nu;
  Eigen::MatrixXd jacobian;
  Eigen::Matrix2d noise = Eigen::Matrix2d::Zero();
};

struct JcbbResult {
  std::vector<int> target_of;  ///< per item: the paired target or -1
  int pairings = 0;
  double nis = 0.0;               ///< joint normalised innovation squared of the pairing
  bool search_truncated = false;  ///< the node cap stopped the search early
  int nodes = 0;                  ///< search nodes expanded (counted against the cap)
};

/// `candidates` holds only individually compatible pairs (the caller's gate).
JcbbResult jcbb(int items, const std::vector<PairingCandidate>& candidates, const Eigen::MatrixXd& covariance,
                double confidence, int max_nodes);

/// The `confidence` quantile of the chi-square distribution with `dof` degrees of freedom.
double chi2_quantile(int dof, double confidence);

}  // namespace lookahead::slam::hybrid
