// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/segslam_options.hpp"

#include <stdexcept>
#include <string>

namespace lookahead::slam::segslam {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

void validate(const SegSlamOptions& o) {
  const SegmentationOptions& s = o.segmentation;
  require(s.lookahead_s >= 0 && s.lookahead_s <= 60, "segmentation.lookahead_s in 0..60");
  require(s.min_segment_updates >= 1, "segmentation.min_segment_updates >= 1");
  require(s.alpha_translation >= 0 && s.alpha_rotation >= 0, "segmentation.alpha_* >= 0");
  require(s.slam_factor > 0 && s.slam_factor <= 1, "segmentation.slam_factor in (0, 1]");
  require(s.max_motion_error > 0, "segmentation.max_motion_error > 0");
  require(s.predictive_threshold >= 0 && s.predictive_threshold <= 1, "segmentation.predictive_threshold in 0..1");
  require(s.predictive_scans >= 1, "segmentation.predictive_scans >= 1");
  const MatchingOptions& m = o.matching;
  require(m.period_updates >= 1, "matching.period_updates >= 1");
  require(m.sample_submaps >= 2, "matching.sample_submaps >= 2");
  require(m.min_separation_s >= 0 && m.proximity_radius > 0, "matching.min_separation_s >= 0, proximity_radius > 0");
  require(m.max_candidates >= 1, "matching.max_candidates >= 1");
  require(m.bin_size > 0, "matching.bin_size > 0");
  require(m.search_radius >= 0 && m.search_angle >= 0, "matching.search_* >= 0");
  require(m.max_search_radius >= 0, "matching.max_search_radius >= 0");
  require(m.icp_iterations >= 1 && m.icp_max_distance > 0, "matching.icp_iterations >= 1, icp_max_distance > 0");
  require(m.icp_sigma > 0 && m.translation_sigma > 0 && m.null_error >= 0, "matching sigmas > 0, null_error >= 0");
  require(m.min_inlier_ratio >= 0 && m.min_inlier_ratio <= 1, "matching.min_inlier_ratio in 0..1");
  require(m.localization_particles >= 10, "matching.localization_particles >= 10");
  const LockingOptions& l = o.locking;
  require(l.lock_max_error >= 0 && l.merge_max_error >= 0, "locking.*_max_error >= 0");
  require(l.lock_min_merged_visits >= 0, "locking.lock_min_merged_visits >= 0");
  require(o.offline.map_samples >= (o.offline.particle_chain ? 0 : 1),
          "offline.map_samples >= 1 (>= 0 with offline.particle_chain: the chain alone)");
}

}  // namespace lookahead::slam::segslam
