// SPDX-License-Identifier: MIT
// Every SegSLAM parameter (Fairfield et al. 2010, SegSLAM sec. 4.3-4.5), nested by component. The
// particle filter steps are the RBPF's and keep their own options (RbpfOptions,
// config/slam/default.yaml); these are the defaults config/segslam/default.yaml mirrors.
#pragma once

#include <cstddef>

namespace lookahead::slam::segslam {

/// Segmentation (SegSLAM sec. 4.3): when a particle starts a new submap.
struct SegmentationOptions {
  /// Look-ahead window [s]: the filter runs this far behind the newest scan, and the
  /// estimate is brought to the present by dead reckoning (SegSLAM sec. 4.1). 0..60.
  double lookahead_s = 3.0;
  /// Minimum segment size in filter updates (SegSLAM sec. 4.3.2, "a minimum segment size"). >= 1.
  int min_segment_updates = 10;
  /// SegSLAM eq. (13)-(14): position error grows by alpha_translation per metre and alpha_rotation per
  /// radian of dead-reckoned motion [m/m], [m/rad] ...
  double alpha_translation = 0.05;
  double alpha_rotation = 0.3;
  /// ... times this factor, the expected share left after SLAM corrections (SegSLAM sec. 4.3.1,
  /// "a slightly less pessimistic dead-reckoning error model"). (0, 1].
  /// Deviation (2D default): 1, the 3D filter and the paper's particle step keep 0.5. The
  /// error also sizes the matching reach and SegSLAM eq. (18)'s sigma_tau (candidate_reach.hpp):
  /// a few-particle filter drifts beyond the reach 0.5 gives before its first re-entry.
  double slam_factor = 1.0;
  /// Segment when the estimated error in the submap reaches this [m]. > 0.
  /// Deviation (2D default): 8 m at slam_factor 1 (4 m at 0.5), not the 1 m of the paper's
  /// particle step (proposal.kind: motion_model): the scan-matching proposal leaves far less
  /// error than SegSLAM eq. (13)-(14) models, and a fresh submap forgets the walls the matcher needs.
  double max_motion_error = 8.0;
  /// SegSLAM eq. (17): segment when the predictive score of the look-ahead window (mean share of its
  /// end points the submap explains) falls below this. 0..1; 0 disables the criterion.
  /// Deviation (2D default): off. Indoors it segments at every room and corner, and each
  /// segment must then be re-entered to keep the map whole. The paper and the 3D filter use 0.5.
  double predictive_threshold = 0.0;
  /// Window scans scored by SegSLAM eq. (17) (evenly spread; bounds the cost). >= 1.
  int predictive_scans = 4;
};

/// Matching (SegSLAM sec. 4.5): when a particle re-enters an old submap.
struct MatchingOptions {
  /// Try matching every this many filter updates (and at every segmentation). >= 1.
  int period_updates = 4;
  /// Submaps placed in a local metric map sample (SegSLAM sec. 4.4). >= 2.
  std::size_t sample_submaps = 40;
  /// Winnowing (SegSLAM sec. 4.5.1): a candidate must have ended this long ago [s] ...
  double min_separation_s = 30.0;
  /// ... and the robot, placed in its frame by the map sample, must be this near its path [m].
  double proximity_radius = 3.0;
  /// At most this many candidates (the nearest) are matched per attempt. >= 1.
  int max_candidates = 2;
  /// Bin size of the point clouds ICP matches [m] ("octree-binned point clouds").
  double bin_size = 0.1;
  /// The guess from the map sample is refined by a coarse search this wide first [m], [rad]
  /// (Deviation: the map sample's guess may be metres off after a long loop, beyond ICP's
  /// basin; the paper's localisation filter covers this with its initial spread).
  double search_radius = 2.0;
  double search_angle = 0.25;
  /// The coarse search, the proximity radius and SegSLAM eq. (18)'s sigma_tau widen with the
  /// SegSLAM eq. (13)-(14) error accumulated since the candidate was left, the search up to this [m]
  /// (candidate_reach.hpp; both filters; the 3D's --max-search-radius overrides it). >= 0.
  /// 2D default 10 m; the 3D filter's 6 m, where its wide stage reaches beyond.
  double max_search_radius = 10.0;
  int icp_iterations = 30;
  double icp_max_distance = 0.4;  ///< correspondences farther than this are outliers [m]
  /// SegSLAM eq. (18): p(err_ICP) = exp(-err^2 / 2 sigma^2) with the mean nearest-neighbour error ...
  double icp_sigma = 0.05;
  /// ... and p(tau^2) = exp(-tau^2 / 2 sigma_tau^2) on the correction's translation [m].
  double translation_sigma = 1.5;
  /// The null match (keep / start a fresh submap) weighs as much as a match with this error.
  double null_error = 0.08;
  /// Match by a separate localisation particle filter weighted by SegSLAM eq. (19) instead of
  /// ICP weighted by SegSLAM eq. (18) (SegSLAM sec. 4.5.2).
  bool use_localization_filter = false;
  /// Particles of that filter, spread over the coarse-search extent around the guess. >= 10
  int localization_particles = 200;
  /// A match with a smaller inlier share of the window's points is discarded. 0..1.
  double min_inlier_ratio = 0.6;
  /// Searches shared by the copies of a segment: particles whose candidates are copies of one
  /// segment (SegMap::first_copy: the same interval along the same parent chain, so the same
  /// frame and the same stretch of the world) screen on the first copy: where a search there
  /// finds nothing, the other copies are not searched; where it finds a match, each copy is
  /// searched itself, so every match offered is fitted to the particle's own copy. In 3D the
  /// wide re-entry search (wide_reentry.hpp) runs on the first copy only, once per update for
  /// all the particles that ask (over a square covering their regions, seg_slam3d_wide.cpp),
  /// and each particle confirms the re-entry on its own copy at its next attempt. false: every
  /// particle searches its own copy (the wide search once per copy), as the paper does.
  /// Deviation (speed): the copies differ only by the particles' noise inside one segment,
  /// and SegSLAM eq. (12) treats them as interchangeable too.
  bool share_by_segment = true;
};

/// Locking and merging (SegSLAM sec. 6; the paper gives the ideas, not the criteria). Deviation:
/// "well known" and "relative position certain" are both judged by the ICP error of the
/// match that re-entered the submap. Off by default: neither lowered the loop-closure error
/// on the Intel loop; the paper's method for reproducing it.
struct LockingOptions {
  /// Lock a particle's re-entered submap (localise in the matched map, write nothing) ...
  bool lock = false;
  /// ... when its match's err_ICP is at most this [m] ...
  double lock_max_error = 0.05;
  /// ... and the matched submap has absorbed at least this many merged re-entries. >= 0
  int lock_min_merged_visits = 0;
  /// Merge a closed re-entered submap into the submap it matched (the cells it observed
  /// that the matched one had not are added; its own map is dropped) ...
  bool merge = false;
  /// ... when its match's err_ICP was at most this [m].
  double merge_max_error = 0.08;
};

/// Offline map sampling (SegSLAM sec. 5.4).
struct OfflineOptions {
  /// Full map samples searched for the minimum-entropy map. >= 1; 0 with particle_chain:
  /// the best particle's chain is the map, no sample is drawn.
  int map_samples = 30;
  /// The best particle's own chain of submaps (the map of its SegSLAM eq. (11) trajectory) is a
  /// candidate of the search too (a deviation: min_entropy_search.hpp). Off in 3D's defaults.
  bool particle_chain = true;
};

struct SegSlamOptions {
  SegmentationOptions segmentation;
  MatchingOptions matching;
  LockingOptions locking;
  OfflineOptions offline;
};

/// Throws std::invalid_argument naming the first option out of its range.
void validate(const SegSlamOptions& options);

}  // namespace lookahead::slam::segslam
