// SPDX-License-Identifier: MIT
// Segmentation heuristics of SegSLAM (Fairfield et al. 2010, SegSLAM sec. 4.3):
//   motion error (SegSLAM eq. (13)-(14)): position_err ~ (alpha_1 v_err + alpha_2 u_err) t, accumulated
//     over the dead-reckoned motion since the submap started, scaled down by the share SLAM
//     is expected to leave;
//   predictive score (SegSLAM eq. (17)): how well the submap predicts the look-ahead window's
//     measurements from dead-reckoned poses; a drop means the robot is leaving the submap;
//   and a minimum segment size.
#pragma once

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"

namespace lookahead::slam::segslam {

/// SegSLAM eq. (13)-(14) for one odometry increment u: the position error it adds [m].
double motion_error_increment(const Pose2& u, const SegmentationOptions& options);

/// The criterion of SegSLAM sec. 4.3 on one particle's submap: `updates` filter updates old, with
/// accumulated motion error `motion_error` [m] and look-ahead predictive score
/// `predictive_score` in [0, 1] (negative: not computed).
bool should_segment(int updates, double motion_error, double predictive_score, const SegmentationOptions& options);

}  // namespace lookahead::slam::segslam
