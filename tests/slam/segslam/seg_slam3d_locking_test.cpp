// SPDX-License-Identifier: MIT
// SegSLAM 3D's locking and merging (Fairfield et al. 2010, sec. 6; seg_slam3d_locking.cpp):
// a locked particle localises in the octree it re-entered without writing it, a closed
// well-registered re-entry is merged into its parent octree (only voxels the parent never
// observed are added) and drops its own, and a match to a merged submap goes to its parent.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <utility>

#include "garage_drive.hpp"
#include "lookahead/slam/segslam/octree_submap_ops.hpp"
#include "lookahead/slam/segslam/seg_map.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam::segslam {
namespace {

using test_data::aisle_back_and_forth;
using test_data::garage_log;
using test_data::map_of;

TEST(OctreeMerge, ParentGainsOnlyTheVoxelsItNeverObserved) {
  const RangeLog3& log = garage_log();
  EvidenceOctree parent = map_of(log, 0, 4);
  const EvidenceOctree before = parent;
  EvidenceOctree child = parent;  // a match copy, written along further sweeps
  for (std::size_t i = 5; i <= 12; ++i) {
    std::vector<Ray3> rays;
    const Pose3& t = *log.sweeps[i].truth;
    for (const Ray3& r : log.sweeps[i].rays) rays.push_back({t * r.origin, t * r.end, r.hit});
    insert_rays(child, rays, {});
  }
  add_child_evidence(parent, child);
  int new_voxels = 0, new_differing = 0, known_changed = 0, child_revised = 0;
  child.for_each_voxel([&](const OctreeKey& k, float l) {
    if (const auto was = before.log_odds(k)) {
      known_changed += *parent.log_odds(k) != *was;
      child_revised += l != *was;
    } else {
      ++new_voxels;
      new_differing += parent.log_odds(k) != l;
    }
  });
  std::printf("%d new voxels, %d revised by the child\n", new_voxels, child_revised);
  EXPECT_GT(new_voxels, 1000);
  EXPECT_EQ(new_differing, 0);
  EXPECT_GT(child_revised, 100);  // the child did write voxels the parent knew ...
  EXPECT_EQ(known_changed, 0);    // ... and the parent kept its own evidence there
  EXPECT_EQ(parent.known_voxels(), before.known_voxels() + static_cast<std::size_t>(new_voxels));
  // The parent was written copy-on-write: what it had is still shared with the old copy.
  EXPECT_LT(EvidenceOctree::distinct_bytes({&parent, &before}),
            parent.memory().total_bytes + before.memory().total_bytes);
  EXPECT_THROW(add_child_evidence(parent, EvidenceOctree(OctreeOptions{0.1})), std::invalid_argument);
}

using OctreeSegMapT = SegMap<EvidenceOctree, Pose4>;

OctreeSubmap submap_of(std::size_t first, std::size_t last, EvidenceOctree map, std::size_t pred = kNoSubmap,
                       std::size_t parent = kNoSubmap) {
  OctreeSubmap s;
  s.interval = {first, last, double(first), double(last)};
  s.predecessor = pred;
  s.parent = parent;
  s.map = std::move(map);
  s.path = {{first, Pose4{}}, {last, Pose4{}}};
  return s;
}

TEST(OctreeMerge, TheSegMapMergesAnOctreeChildAndRedirectsToItsParent) {
  const RangeLog3& log = garage_log();
  OctreeSegMapT m;
  const std::size_t a = m.add(submap_of(0, 4, map_of(log, 0, 4)));
  const std::size_t b = m.add(submap_of(4, 8, map_of(log, 4, 8), a));
  EvidenceOctree reentry = m.at(a).map;
  insert_rays(reentry, {{Eigen::Vector3d(10, 7, 20), Eigen::Vector3d(12, 7, 20), true}}, {});  // far above the deck
  const std::size_t c = m.add(submap_of(8, 12, reentry, b, a));
  const std::size_t known = m.at(a).map.known_voxels();
  EXPECT_EQ(m.map_holder(c), c);  // not merged: its own map
  ASSERT_TRUE(m.merge_into_parent(c, add_child_evidence));
  EXPECT_GT(m.at(a).map.known_voxels(), known);
  EXPECT_EQ(m.at(a).merged_visits, 1);
  EXPECT_TRUE(m.at(c).merged);
  EXPECT_EQ(m.at(c).map.known_voxels(), 0U);  // the child dropped its map
  EXPECT_EQ(m.map_count(), 2U);
  EXPECT_EQ(m.live_count(), 3U);
  EXPECT_EQ(m.map_holder(c), a);  // a match to the merged child is a match to its parent
  EXPECT_EQ(m.map_holder(a), a);
  EXPECT_EQ(m.map_holder(b), b);
}

TEST(SegSlam3dLocking, RejectsImpossibleLockingOptions) {
  SegSlam3dOptions o;
  o.segslam.locking.lock_max_error = -0.1;
  EXPECT_THROW(SegSlam3d{o}, std::invalid_argument);
  o = {};
  o.segslam.locking.merge_max_error = -1;
  EXPECT_THROW(SegSlam3d{o}, std::invalid_argument);
  o = {};
  o.segslam.locking.lock_min_merged_visits = -1;
  EXPECT_THROW(SegSlam3d{o}, std::invalid_argument);
  const SegSlam3dOptions defaults;
  EXPECT_FALSE(defaults.segslam.locking.lock);  // off by default, as in 2D
  EXPECT_FALSE(defaults.segslam.locking.merge);
}

SegSlam3dOptions options_for_aisle(bool lock_and_merge) {
  SegSlam3dOptions o = test_data::aisle_options(4);
  o.segslam.locking.lock = o.segslam.locking.merge = lock_and_merge;
  // Generous: the test is about what locking does, not about the thresholds.
  o.segslam.locking.lock_max_error = o.segslam.locking.merge_max_error = 0.2;
  o.extras.record_attempts = true;
  return o;
}

TEST(SegSlam3dLocking, LockedParticlesWriteNothingReentriesMergeAndMapsStopGrowing) {
  SegSlam3d filter(options_for_aisle(true));
  // The first copy seen of each locked submap (by entry sweep and matched parent): every
  // particle locked there copied the same parent octree and must still share all of it.
  std::map<std::pair<std::size_t, std::size_t>, EvidenceOctree> at_lock;
  std::size_t locked_steps = 0, unshared = 0;
  for (const RangeSweep& s : aisle_back_and_forth().sweeps) {
    filter.add_sweep(s);
    for (const SegParticle3& p : filter.particles()) {
      if (!p.submap.locked) continue;
      const auto it =
          at_lock.emplace(std::make_pair(p.submap.interval.first_scan, p.submap.parent), p.submap.map).first;
      p.submap.map.for_each_voxel_not_shared_with(it->second,
                                                  [&](const OctreeKey&, float, std::optional<float>) { ++unshared; });
      ++locked_steps;
    }
  }
  filter.finish();
  const SegSlam3dStatistics& st = filter.statistics();
  const OctreeSegMap& segmap = filter.segmap();
  std::printf(
      "%zu sweeps: %zu matches, %zu locked (%zu locked particle steps), %zu merged; %zu of %zu submaps hold maps\n",
      aisle_back_and_forth().sweeps.size(), st.matches, st.locked, st.locked_updates, st.merged, segmap.map_count(),
      segmap.live_count());
  EXPECT_GT(st.locked, 0U);
  EXPECT_GT(locked_steps, 10U);
  EXPECT_EQ(unshared, 0U);  // no locked octree was written
  EXPECT_GT(st.locked_updates, 10U);
  EXPECT_GT(st.merged, 0U);
  std::size_t merged = 0;
  for (std::size_t id = 0; id < segmap.id_bound(); ++id) {
    if (!segmap.contains(id) || !segmap.at(id).merged) continue;
    ++merged;
    EXPECT_EQ(segmap.at(id).map.known_voxels(), 0U);
    EXPECT_FALSE(segmap.at(segmap.at(id).parent).merged);
  }
  EXPECT_EQ(segmap.live_count() - segmap.map_count(), merged);
  // Matches to a merged submap went to its parent: no candidate considered was merged (its
  // octree is empty), and no match taken was to one.
  for (const MatchAttempt3& a : st.attempts) {
    if (segmap.contains(a.candidate)) EXPECT_FALSE(segmap.at(a.candidate).merged) << "sweep " << a.sweep;
  }
  for (const MatchEvent3& e : st.match_events) {
    if (segmap.contains(e.candidate)) EXPECT_FALSE(segmap.at(e.candidate).merged) << "sweep " << e.sweep;
  }
  // Still localised: the locked particles did not lose the robot.
  const Eigen::Vector3d truth = aisle_back_and_forth().sweeps.back().truth->translation();
  EXPECT_LT((filter.estimate().position() - truth).norm(), 1.0);
  // Merging keeps the maps from growing with the legs driven: off, every stored submap keeps
  // a map (and nothing is locked or merged).
  SegSlam3d off(options_for_aisle(false));
  test_data::run_filter(off, aisle_back_and_forth());
  EXPECT_EQ(off.statistics().locked + off.statistics().merged + off.statistics().locked_updates, 0U);
  EXPECT_EQ(off.segmap().map_count(), off.segmap().live_count());
  EXPECT_LT(segmap.map_count(), off.segmap().map_count());
}

}  // namespace
}  // namespace lookahead::slam::segslam
