// SPDX-License-Identifier: MIT
#include "segmentation.hpp"

#include <cmath>

namespace lookahead::slam::segslam {

double motion_error_increment(const Pose2& u, const SegmentationOptions& o) {
  // v_err t ~ distance driven, u_err t ~ angle turned: heading error dominates, so hard
  // turns favour segmentation (SegSLAM sec. 4.3.1).
  return o.slam_factor * (o.alpha_translation * u.norm() + o.alpha_rotation * std::abs(u.theta));
}

bool should_segment(int updates, double motion_error, double predictive_score, const SegmentationOptions& o) {
  if (updates < o.min_segment_updates) return false;
  if (motion_error >= o.max_motion_error) return true;
  return predictive_score >= 0.0 && predictive_score < o.predictive_threshold;
}

}  // namespace lookahead::slam::segslam
