// SPDX-License-Identifier: MIT
// The improved proposal of Grisetti, Stachniss, Burgard (IEEE T-RO 2007), sec. III-A/B:
// around the scan-matched mode x^ draw K poses x_j, evaluate
//   tau(x_j) = p(z_t | m, x_j) p(x_j | x_{t-1}, u_t)                        (Grisetti 2007 eq. (11))
// and take
//   mu    = 1/eta sum_j x_j tau(x_j)                                        (Grisetti 2007 eq. (12))
//   eta   = sum_j tau(x_j)                                                  (Grisetti 2007 eq. (14))
// The particle's new pose is mu and its weight is multiplied by eta (Grisetti 2007 eq. (16)).
// Deviation, as GMapping's released code and measured (docs/algorithms/rbpf.md): the
// particles' spread enters as a motion-model draw of the scan matcher's start, not as a draw
// from N(mu, Sigma) (eq. (13)). Sigma is fitted on 27 points a few centimetres apart, on a
// tempered likelihood nearly flat across them, so such a draw's spread is the lattice's, not
// the posterior's; every particle would write that noise into its map and match the next
// scans against it, and the whole cloud drifts with it, out of reach of any weighting (MIT
// CSAIL: headings 0.4 deg apart, the cloud 3 cm wide, while the error grows to 0.3 m).
#pragma once

#include <array>
#include <utility>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

/// How a particle draws its next pose.
enum class ProposalKind {
  /// The improved proposal (Grisetti 2007 sec. III-A/B, eq. (11)-(16)): scan match from a
  /// motion-model draw, then the mean around the match; the odometry model where the match fails.
  kScanMatch,
  /// The standard proposal: sample the odometry model, weight by the scan's likelihood
  /// (Grisetti 2007 eq. (5); the particle step of P-SLAM and SegSLAM).
  kMotionModel,
};

/// proposal.kind in YAML (a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<ProposalKind, const char*>, 2> choice_names(ProposalKind) {
  return {{{ProposalKind::kScanMatch, "scan_match"}, {ProposalKind::kMotionModel, "motion_model"}}};
}

struct ProposalOptions {
  ProposalKind kind = ProposalKind::kScanMatch;
  double kernel_linear = 0.025;    ///< spacing of the K = 27 points in x and y [m]
  double kernel_angular = 0.0125;  ///< spacing in theta [rad]
};

struct ProposalMean {
  Pose2 mean;            ///< mu, the particle's new pose x_t^(i)
  double log_eta = 0.0;  ///< log of the weight factor eta
};

/// mu (eq. (12)) and the weight factor eta (eq. (14)), with the kernel points read through
/// `lookup`: a particle's step, and the pose of the scans tracked between updates.
ProposalMean improved_proposal(const OccupancyGrid& grid, const Pose2& previous, const Pose2& u, const Pose2& mode,
                               const PreparedScan& scan, const LikelihoodFieldModel& likelihood,
                               const OdometryMotionModel& motion, const ProposalOptions& options, FieldLookup lookup);

}  // namespace lookahead::slam
