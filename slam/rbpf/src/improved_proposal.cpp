// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/improved_proposal.hpp"

#include <Eigen/Core>
#include <array>
#include <cmath>

namespace lookahead::slam {

namespace {

// The kernel's mean, in offsets from the mode, and its weight.
struct FittedProposal {
  Eigen::Vector3d mu;
  double log_eta = 0.0;
};

FittedProposal fit_proposal(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u, const Pose2& mode,
                            const PreparedScan& scan, const LikelihoodFieldModel& likelihood,
                            const OdometryMotionModel& motion, const ProposalOptions& options, FieldLookup lookup) {
  // K = 27 points on a 3x3x3 lattice centred on the mode; offsets kept relative to the mode
  // so angles never wrap inside the sums.
  std::array<Eigen::Vector3d, 27> offsets;
  std::array<double, 27> log_tau;
  int k = 0;
  double max_log = -INFINITY;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      for (int a = -1; a <= 1; ++a, ++k) {
        offsets[k] = {i * options.kernel_linear, j * options.kernel_linear, a * options.kernel_angular};
        const Pose2 x{mode.x + offsets[k].x(), mode.y + offsets[k].y(), normalize_angle(mode.theta + offsets[k].z())};
        log_tau[k] = likelihood.log_likelihood(grid, x, scan, lookup) + motion.log_density(previous, u, x);
        max_log = std::max(max_log, log_tau[k]);
      }
    }
  }
  double eta = 0.0;  // scaled by exp(-max_log) to stay in range
  Eigen::Vector3d mu = Eigen::Vector3d::Zero();
  for (int j = 0; j < 27; ++j) {
    const double tau = std::exp(log_tau[j] - max_log);
    eta += tau;
    mu += tau * offsets[j];
  }
  mu /= eta;
  return {mu, max_log + std::log(eta)};
}

}  // namespace

ProposalMean improved_proposal(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u, const Pose2& mode,
                               const PreparedScan& scan, const LikelihoodFieldModel& likelihood,
                               const OdometryMotionModel& motion, const ProposalOptions& options, FieldLookup lookup) {
  const FittedProposal f = fit_proposal(grid, previous, u, mode, scan, likelihood, motion, options, lookup);
  ProposalMean out;
  out.mean = {mode.x + f.mu.x(), mode.y + f.mu.y(), normalize_angle(mode.theta + f.mu.z())};
  out.log_eta = f.log_eta;
  return out;
}

}  // namespace lookahead::slam
