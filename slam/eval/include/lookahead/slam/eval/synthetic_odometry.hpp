// SPDX-License-Identifier: MIT
// Synthetic wheel odometry from a true trajectory, for logs that have real scans and
// corrected poses but no raw odometry. Figures computed on its output must be labelled
// "real scans, synthetic odometry".
//
// Drift model (seeded; Pioneer-like magnitudes). For consecutive true poses a, b let
// d = a^-1 (+) b = (dx, dy, dth) and s = |(dx, dy)|. The odometry increment is
//   dx'  = dx + N(0, (k_t s)^2)
//   dy'  = dy + N(0, (k_t s)^2)
//   dth' = dth + N(0, (k_r |dth| + k_rt s)^2) + beta s
// where the heading bias beta [rad/m] is drawn once per run from N(0, k_b^2) and then
// drifts as a random walk with step N(0, (k_bw s)^2). Odometry starts at the first true pose.
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam {

struct OdometryDriftModel {
  double k_t = 0.03;    ///< translation noise per metre (3 %)
  double k_r = 0.05;    ///< rotation noise per radian turned (5 %)
  double k_rt = 0.01;   ///< rotation noise per metre driven [rad/m] (0.57 deg/m)
  double k_b = 0.005;   ///< std of the initial heading bias [rad/m] (0.29 deg/m)
  double k_bw = 0.001;  ///< random-walk step of the bias per metre [rad/m/m]
  std::uint64_t seed = 1;
};

std::vector<Pose2> synthesize_odometry(const std::vector<Pose2>& truth, const OdometryDriftModel& model);

}  // namespace lookahead::slam
