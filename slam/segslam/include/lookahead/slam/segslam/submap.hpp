// SPDX-License-Identifier: MIT
// A SegSLAM submap (Fairfield, Kantor, Wettergreen, "Segmented SLAM in three-dimensional
// environments", J. Field Robotics 2010, SegSLAM sec. 4.4 and Table I): a map, its interval
// (t_s, t_e), the particle's entry and exit poses T_s, T_e in the submap's own frame, the
// submap the particle came from (temporal predecessor) and, for a match, the parent it was
// copied from (copy-on-write: the child shares the parent's map and stores only changes).
//
// Generic over the map and pose types: `Map` must be cheap to copy (copy-on-write) and
// `Pose` must offer compose(), inverse() and between() (Pose2 here, an SE(3) pose in 3D).
#pragma once

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace lookahead::slam::segslam {

inline constexpr std::size_t kNoSubmap = std::numeric_limits<std::size_t>::max();

/// The interval of a submap in scans of the log: [first_scan, last_scan]. A submap entered
/// at scan k starts at k (the entry pose is the particle's pose at k) and its predecessor
/// ends at k: neighbours share one scan, the switch point.
struct Interval {
  std::size_t first_scan = 0;
  std::size_t last_scan = 0;
  double t_start = 0.0;  ///< t_s [s]
  double t_end = 0.0;    ///< t_e [s]
  friend bool operator==(const Interval& a, const Interval& b) {
    return a.first_scan == b.first_scan && a.last_scan == b.last_scan;
  }
  /// Temporally compatible: the intervals overlap at most in their shared switch scan.
  [[nodiscard]] bool compatible_with(const Interval& o) const {
    return last_scan <= o.first_scan || o.last_scan <= first_scan;
  }
};

template <class Map, class Pose>
struct Submap {
  Interval interval;
  Pose entry;                           ///< T_s: the particle's pose at interval.first_scan, in this submap's frame
  Pose exit;                            ///< T_e: its pose at interval.last_scan (set when the submap is closed)
  std::size_t predecessor = kNoSubmap;  ///< the submap the particle left to enter this one
  std::size_t parent = kNoSubmap;       ///< the matched submap this one copies (same frame)
  Map map;
  /// The particle's poses at its filter updates inside the interval (scan, pose in frame).
  std::vector<std::pair<std::size_t, Pose>> path;
  /// Locked (SegSLAM sec. 6: "well-known segments can be locked to prevent updates, such that
  /// particles that reenter those segments perform localization"): `map` is never written.
  bool locked = false;
  /// Merged into its parent (SegSLAM sec. 6): its evidence went into the parent's map and `map` was
  /// dropped; interval, poses and links stay, so trajectories still pass through it.
  bool merged = false;
  /// Re-entries merged into this submap so far (how well known it is).
  int merged_visits = 0;
};

}  // namespace lookahead::slam::segslam
