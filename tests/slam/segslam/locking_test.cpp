// SPDX-License-Identifier: MIT
// Locking and merging (Fairfield et al. 2010, sec. 6): a re-entered submap that registers
// well is localised in without being written, and closed re-entries are merged into the
// submap they matched, so repeated traversals add no maps.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "../test_world.hpp"
#include "lookahead/slam/segslam/grid_submap_ops.hpp"
#include "lookahead/slam/segslam/seg_map.hpp"
#include "lookahead/slam/segslam/seg_slam.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {
namespace {

struct CellSet {  // a toy map: the cells observed
  std::set<int> cells;
};
using S = Submap<CellSet, Pose2>;

S toy(std::size_t first, std::size_t last, std::set<int> cells, std::size_t pred = kNoSubmap,
      std::size_t parent = kNoSubmap) {
  S s;
  s.interval = {first, last, double(first), double(last)};
  s.exit = {1, 0, 0};
  s.predecessor = pred;
  s.parent = parent;
  s.map.cells = std::move(cells);
  s.path = {{first, {}}, {last, s.exit}};
  return s;
}

TEST(SegMapMerge, ChildEvidenceGoesToTheParentAndTheChildDropsItsMap) {
  SegMap<CellSet, Pose2> m;
  const std::size_t a = m.add(toy(0, 10, {1, 2}));
  const std::size_t b = m.add(toy(10, 20, {7}, a));
  const std::size_t c = m.add(toy(20, 30, {1, 2, 3}, b, a));  // re-entry of a that saw cell 3
  ASSERT_EQ(m.map_count(), 3u);
  const auto add = [](CellSet& into, const CellSet& child) {
    into.cells.insert(child.cells.begin(), child.cells.end());
  };
  EXPECT_FALSE(m.merge_into_parent(b, add));  // no parent: nothing to merge into
  ASSERT_TRUE(m.merge_into_parent(c, add));
  EXPECT_EQ(m.map_count(), 2u);
  EXPECT_EQ(m.live_count(), 3u);  // the child's interval and poses stay
  EXPECT_EQ(m.at(a).map.cells, (std::set<int>{1, 2, 3}));
  EXPECT_EQ(m.at(a).merged_visits, 1);
  EXPECT_TRUE(m.at(c).merged);
  EXPECT_TRUE(m.at(c).map.cells.empty());
  EXPECT_FALSE(m.merge_into_parent(c, add));  // once only
  // Trajectories still run through the merged child.
  S open = toy(30, 40, {}, c);
  EXPECT_EQ(temporal_chain(m, open).size(), 4u);
}

TEST(GridMerge, ParentGainsTheChildsNewCellsAndKeepsItsOwn) {
  const auto world = test::room_world();
  OccupancyGrid parent;
  for (double x = 1; x < 5; x += 0.5) insert_scan(parent, {x, 1, 0}, test::simulate_scan(world, {x, 1, 0}, {}), {});
  const OccupancyGrid before = parent;
  OccupancyGrid child = parent;
  insert_scan(child, {8.5, 5.0, M_PI}, test::simulate_scan(world, {8.5, 5.0, M_PI}, {}), {});
  add_child_evidence(parent, child);
  CellIndex lo, hi;
  ASSERT_TRUE(child.known_bounds(lo, hi));
  int new_cells = 0, new_cells_differing = 0, known_cells_changed = 0, child_revised = 0;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const CellIndex c{x, y};
      if (before.is_known(c)) {
        known_cells_changed += parent.raw_log_odds(c) != before.raw_log_odds(c);
        child_revised += child.raw_log_odds(c) != before.raw_log_odds(c);
      } else if (child.is_known(c)) {
        ++new_cells;
        new_cells_differing +=
            parent.raw_log_odds(c) != child.raw_log_odds(c) || parent.is_obstacle(c) != child.is_obstacle(c);
      }
    }
  }
  EXPECT_GT(new_cells, 100);
  EXPECT_EQ(new_cells_differing, 0);
  EXPECT_GT(child_revised, 0);        // the child did write cells the parent knew ...
  EXPECT_EQ(known_cells_changed, 0);  // ... and the parent kept its own evidence there
  // The distance field follows the new obstacles.
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!before.is_known({x, y}) && child.is_obstacle({x, y})) EXPECT_EQ(parent.dist2({x, y}), 0);
    }
  }
  // Tiles the child never wrote are still shared with the parent as it was.
  EXPECT_GT(parent.tiles_shared_with(before), 0u);
}

// Twice around the inner box of the test room (odometry with a heading bias), as in
// seg_slam_test: the second lap re-enters the first lap's submaps.
std::vector<LaserScan> two_loops() {
  const auto world = test::room_world();
  std::vector<LaserScan> out;
  Pose2 truth{1.5, 1.0, 0.0}, odom = truth;
  const std::vector<Pose2> legs{{7.0, 0, 0}, {0, 0, M_PI / 2}, {4.0, 0, 0}, {0, 0, M_PI / 2}};
  double t = 0;
  for (int lap = 0; lap < 4; ++lap) {
    for (const Pose2& leg : legs) {
      const int steps = leg.x > 0 ? static_cast<int>(leg.x / 0.1) : 10;
      for (int i = 0; i < steps; ++i) {
        const Pose2 step{leg.x / steps, 0, leg.theta / steps};
        truth = truth.compose(step);
        odom = odom.compose({step.x, 0, step.theta + step.x * 0.03});
        out.push_back(test::simulate_scan(world, truth, odom, t += 0.2));
      }
    }
  }
  return out;
}

SegSlam make_filter(bool lock_and_merge) {
  RbpfOptions rbpf;
  rbpf.particles = 3;
  rbpf.threads = 1;
  rbpf.linear_update = 0.3;
  SegSlamOptions o;
  o.segmentation.min_segment_updates = 6;
  o.segmentation.max_motion_error = 0.4;
  o.matching.min_separation_s = 10;
  o.locking.lock = o.locking.merge = lock_and_merge;
  return SegSlam(rbpf, o);
}

TEST(SegSlamLocking, LockedSubmapsAreNotWrittenAndReentriesMerge) {
  SegSlam filter = make_filter(true);
  // The first copy seen of each locked submap (by entry scan and matched parent): every
  // particle locked there copied the same parent map and must still share all its tiles.
  std::map<std::pair<std::size_t, std::size_t>, OccupancyGrid> at_lock;
  std::size_t locked_steps = 0;
  for (const LaserScan& s : two_loops()) {
    filter.add_scan(s);
    for (const SegParticle& p : filter.particles()) {
      if (!p.submap.locked) continue;
      const auto key = std::make_pair(p.submap.interval.first_scan, p.submap.parent);
      const auto it = at_lock.emplace(key, p.submap.map).first;
      EXPECT_EQ(p.submap.map.tiles_shared_with(it->second), p.submap.map.tile_count());
      ++locked_steps;
    }
  }
  filter.finish();
  const SegSlamStatistics& st = filter.statistics();
  EXPECT_GT(st.locked, 0u);
  EXPECT_GT(locked_steps, 20u);
  EXPECT_GT(st.merged, 0u);
  EXPECT_EQ(filter.segmap().live_count() - filter.segmap().map_count(), [&] {
    std::size_t merged = 0;
    for (std::size_t id = 0; id < filter.segmap().id_bound(); ++id) {
      merged += filter.segmap().contains(id) && filter.segmap().at(id).merged;
    }
    return merged;
  }());
}

TEST(SegSlamLocking, MergingKeepsTheMapsFromGrowingWithLaps) {
  std::size_t maps[2];
  for (int on = 0; on <= 1; ++on) {
    SegSlam filter = make_filter(on == 1);
    for (const LaserScan& s : two_loops()) filter.add_scan(s);
    filter.finish();
    maps[on] = filter.segmap().map_count();
  }
  EXPECT_LT(maps[1], maps[0]);
}

}  // namespace
}  // namespace lookahead::slam::segslam
