// SPDX-License-Identifier: MIT
// The improved proposal of Grisetti, Stachniss, Burgard (IEEE T-RO 2007), sec. III-A/B:
// around the scan-matched mode x^ draw K poses x_j, evaluate
//   tau(x_j) = p(z_t | m, x_j) p(x_j | x_{t-1}, u_t)                        (Grisetti 2007 eq. (11))
// and fit a Gaussian
//   mu    = 1/eta sum_j x_j tau(x_j)                                        (Grisetti 2007 eq. (12))
//   Sigma = 1/eta sum_j tau(x_j) (x_j - mu)(x_j - mu)^T                     (Grisetti 2007 eq. (13))
//   eta   = sum_j tau(x_j)                                                  (Grisetti 2007 eq. (14))
// The new pose is sampled from N(mu, Sigma) and the weight is multiplied by eta (Grisetti 2007 eq. (16)).
// GMapping's released code takes mu itself instead of sampling and draws from the motion model
// before matching instead; ProposalSampling chooses between the two.
#pragma once

#include <array>
#include <random>
#include <utility>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

/// How a particle draws its next pose.
enum class ProposalKind {
  /// The improved proposal (Grisetti 2007 sec. III-A/B, eq. (11)-(16)): scan match, then sample
  /// the Gaussian fitted around the match; the odometry model where the match fails.
  kScanMatch,
  /// The standard proposal: sample the odometry model, weight by the scan's likelihood
  /// (Grisetti 2007 eq. (5); the particle step of P-SLAM and SegSLAM).
  kMotionModel,
};

/// proposal.kind in YAML (a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<ProposalKind, const char*>, 2> choice_names(ProposalKind) {
  return {{{ProposalKind::kScanMatch, "scan_match"}, {ProposalKind::kMotionModel, "motion_model"}}};
}

/// Where a particle's randomness enters the improved proposal (proposal.kind: scan_match).
enum class ProposalSampling {
  /// As published (Grisetti 2007 sec. III-B): match from the odometry prediction x_{t-1} (+) u,
  /// draw the pose from N(mu, Sigma).
  kKernel,
  /// As GMapping's released code: draw the matcher's start from the motion model
  /// p(x | x_{t-1}, u), match from there, and the particle takes mu (eq. (12)), read on the
  /// bilinear field. Deviation, measured (docs/algorithms/rbpf.md): Sigma is fitted on 27 points
  /// spaced a few centimetres apart, on a tempered likelihood that is nearly flat across them,
  /// so the draw's spread is the lattice's rather than the posterior's. Every particle writes
  /// that noise into its map and the next scans match against it: the whole cloud drifts with
  /// it, out of reach of any weighting (MIT CSAIL: headings 0.4 deg apart, the cloud 3 cm wide,
  /// while the error against the reference grows to 0.3 m).
  kStart,
};

/// proposal.sampling in YAML.
constexpr std::array<std::pair<ProposalSampling, const char*>, 2> choice_names(ProposalSampling) {
  return {{{ProposalSampling::kKernel, "kernel"}, {ProposalSampling::kStart, "start"}}};
}

struct ProposalOptions {
  ProposalKind kind = ProposalKind::kScanMatch;
  ProposalSampling sampling = ProposalSampling::kStart;
  double kernel_linear = 0.025;    ///< spacing of the K = 27 points in x and y [m]
  double kernel_angular = 0.0125;  ///< spacing in theta [rad]
  /// Floor on the fitted standard deviations, a fraction of the kernel spacing: a likelihood
  /// peaked on one kernel point would otherwise give a zero covariance.
  double min_sigma_fraction = 0.25;
};

struct ProposalDraw {
  Pose2 pose;            ///< x_t^(i) ~ N(mu, Sigma)
  Pose2 mean;            ///< mu
  double log_eta = 0.0;  ///< log of the weight factor eta
};

/// mu alone (eq. (12)), for a pose estimate that is not a particle's draw; `lookup` is how the
/// kernel points read the distance field.
Pose2 improved_proposal_mean(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u, const Pose2& mode,
                             const PreparedScan& scan, const LikelihoodFieldModel& likelihood,
                             const OdometryMotionModel& motion, const ProposalOptions& options, FieldLookup lookup);

ProposalDraw draw_improved_proposal(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u, const Pose2& mode,
                                    const PreparedScan& scan, const LikelihoodFieldModel& likelihood,
                                    const OdometryMotionModel& motion, const ProposalOptions& options,
                                    std::mt19937_64& rng);

/// ProposalSampling::kStart: the pose is mu itself (eq. (12)) and the weight factor eta
/// (eq. (14)), with the kernel points read through `lookup`.
ProposalDraw improved_proposal_at_mean(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u,
                                       const Pose2& mode, const PreparedScan& scan,
                                       const LikelihoodFieldModel& likelihood, const OdometryMotionModel& motion,
                                       const ProposalOptions& options, FieldLookup lookup);

}  // namespace lookahead::slam
