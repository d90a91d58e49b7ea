// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/segslam_config.hpp"

#include <stdexcept>

#include "lookahead/slam/config/yaml_sections.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

using segslam::SegSlamOptions;

// The single list of keys, walked by the loader and the dumper.
template <typename V>
void visit_sections(SegSlamOptions& o, V&& v) {
  auto& s = o.segmentation;
  v.section("segmentation");
  v("lookahead_s", s.lookahead_s, "look-ahead window; the filter runs this far behind [s]");
  v("min_segment_updates", s.min_segment_updates, "minimum segment size [filter updates]");
  v("alpha_translation", s.alpha_translation, "SegSLAM eq. (13)-(14) error per metre driven [m/m]");
  v("alpha_rotation", s.alpha_rotation, "SegSLAM eq. (13)-(14) error per radian turned [m/rad]");
  v("slam_factor", s.slam_factor, "share of the dead-reckoning error SLAM leaves");
  v("max_motion_error", s.max_motion_error, "segment at this estimated error [m]");
  v("predictive_threshold", s.predictive_threshold, "SegSLAM eq. (17): segment below this window score (0 = off)");
  v("predictive_scans", s.predictive_scans, "window scans scored by SegSLAM eq. (17)");
  auto& m = o.matching;
  v.section("matching");
  v("period_updates", m.period_updates, "try matching every n updates");
  v("sample_submaps", m.sample_submaps, "submaps in a local metric map sample");
  v("min_separation_s", m.min_separation_s, "candidate must have ended this long ago [s]");
  v("proximity_radius", m.proximity_radius, "robot must be this near the candidate's path [m]");
  v("max_candidates", m.max_candidates, "candidates matched per attempt");
  v("bin_size", m.bin_size, "ICP point bins [m]");
  v("search_radius", m.search_radius, "coarse search before ICP, translation [m]");
  v("search_angle", m.search_angle, "coarse search before ICP, rotation [rad]");
  v("max_search_radius", m.max_search_radius, "the search widens with the loop's error up to this [m]");
  v("icp_iterations", m.icp_iterations, "ICP iterations");
  v("icp_max_distance", m.icp_max_distance, "ICP outlier distance [m]");
  v("icp_sigma", m.icp_sigma, "SegSLAM eq. (18) sigma of the ICP error [m]");
  v("translation_sigma", m.translation_sigma, "SegSLAM eq. (18) sigma of the correction [m]");
  v("null_error", m.null_error, "the null match weighs as a match of this error [m]");
  v("min_inlier_ratio", m.min_inlier_ratio, "matches with fewer inliers are discarded");
  v("use_localization_filter", m.use_localization_filter,
    "match by a localisation filter (SegSLAM eq. (19)), not ICP (eq. (18))");
  v("localization_particles", m.localization_particles, "particles of the localisation filter");
  v("share_by_segment", m.share_by_segment, "copies of one segment share the searches that find nothing");
  auto& l = o.locking;
  v.section("locking");
  v("lock", l.lock, "lock well-registered re-entered submaps (localise, no writes)");
  v("lock_max_error", l.lock_max_error, "lock when the re-entry match error is at most this [m]");
  v("lock_min_merged_visits", l.lock_min_merged_visits, "and the matched submap has this many merged re-entries");
  v("merge", l.merge, "merge closed well-registered re-entries into the matched submap");
  v("merge_max_error", l.merge_max_error, "merge when the re-entry match error was at most this [m]");
  v.section("offline");
  v("map_samples", o.offline.map_samples, "map samples of the minimum-entropy search");
  v("particle_chain", o.offline.particle_chain, "the best particle's own chain of submaps is a candidate map too");
}

}  // namespace

SegSlamOptions parse_segslam_options(const std::string& yaml, const std::string& source, const SegSlamOptions& base) {
  return config::parse_options(
      yaml, source, base, [](SegSlamOptions& o, auto& v) { visit_sections(o, v); },
      [](const SegSlamOptions& o) { segslam::validate(o); });
}

SegSlamOptions load_segslam_options(const std::string& path, const SegSlamOptions& base) {
  return parse_segslam_options(config::read_text_file(path), path, base);
}

std::string dump_segslam_options(const SegSlamOptions& options) {
  return config::dump_options(options, [](SegSlamOptions& o, auto& v) { visit_sections(o, v); });
}

}  // namespace lookahead::slam
