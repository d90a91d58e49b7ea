// SPDX-License-Identifier: MIT
// SegSLAM 3D's locking and merging (Fairfield et al. 2010, SegSLAM sec. 6: "well-known segments can
// be locked to prevent updates, such that particles that reenter those segments perform
// localization"; "submaps can be quickly merged by adding the evidence grids when their
// relative positions become certain"), with the 2D filter's options and criteria
// (LockingOptions, seg_slam.cpp). Off by default, as in 2D.
//
// Deviation (as in 2D): the paper gives the ideas, not the criteria; "well known" and
// "relative position certain" are both judged by SegSLAM eq. (18)'s err_ICP of the match that re-entered
// the submap (in 3D the structure points' error, octree_submap_ops.hpp).
//
// Why it matters more in 3D: ray insertion into the octree is the largest part of a
// particle's step, and a locked particle skips it (advance() in seg_slam3d.cpp); its submap
// keeps sharing every brick of the matched octree. Merging bounds the maps a loop driven again
// and again adds: a merged re-entry keeps its interval, poses and links but no map.
#include "lookahead/slam/segslam/seg_slam3d.hpp"

namespace lookahead::slam::segslam {

bool SegSlam3d::locks_on_entry(double entry_error, std::size_t candidate) const {
  const LockingOptions& o = options_.segslam.locking;
  return o.lock && entry_error <= o.lock_max_error && segmap_.at(candidate).merged_visits >= o.lock_min_merged_visits;
}

void SegSlam3d::merge_if_registered(std::size_t id, double entry_error) {
  const LockingOptions& o = options_.segslam.locking;
  const std::size_t parent = segmap_.at(id).parent;
  if (!o.merge || parent == kNoSubmap || entry_error > o.merge_max_error) return;
  if (!segmap_.merge_into_parent(id, add_child_evidence)) return;
  ++stats_.merged;
  // The parent's map changed and the child holds none: their match targets are stale.
  targets_.erase(parent);
  targets_.erase(id);
}

std::size_t SegSlam3d::map_holder(std::size_t id) const {
  // A merged submap's parent shares its frame and holds its evidence (a parent is never
  // merged after its children were: only a submap being closed is merged).
  return segmap_.map_holder(id);
}

}  // namespace lookahead::slam::segslam
