// SPDX-License-Identifier: MIT
// The SegSLAM 3D coarse search's branch and bound against its brute-force oracle (the
// exhaustive search), and its bound levels (built once per candidate) against their
// definition: matching must give the same result from them as the exhaustive search did.
#include "lookahead/slam/segslam/level_coarse_search.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "lookahead/slam/octree/ray_insertion.hpp"
#include "lookahead/slam/segslam/octree_submap_ops.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam::segslam {
namespace {

struct Scene {
  EvidenceOctree map;  // sweeps 5-12 of a short garage drive, true poses
  SweepWindow window;  // sweeps 8-11 in the true level frame of sweep 8
  Pose4 truth;         // the robot at sweep 8
};

const Scene& scene() {
  static const Scene s = [] {
    World3 w = make_garage_world(1, 0.2);
    w.route.resize(3);
    const RangeLog3 log = simulate_cave_crawler(w, {}, 1);
    Scene out;
    for (std::size_t i = 5; i <= 12; ++i) {
      std::vector<Ray3> rays;
      const Pose3& t = *log.sweeps[i].truth;
      for (const Ray3& r : log.sweeps[i].rays) rays.push_back({t * r.origin, t * r.end, r.hit});
      insert_rays(out.map, rays, {});
    }
    out.truth = Pose4::level_of(*log.sweeps[8].truth);
    const Pose3 to_start = out.truth.level_pose3().inverse();
    Points3 all;
    for (std::size_t i = 8; i <= 11; ++i) {
      for (const Ray3& r : log.sweeps[i].rays) {
        if (r.hit) all.push_back(to_start * (*log.sweeps[i].truth * r.end));
      }
    }
    out.window = make_sweep_window(all, 300, segslam3d_defaults().matching);
    return out;
  }();
  return s;
}

// A grid pose by its indices, and its score.
struct Scored {
  int a, i, j, score;
};

// The peaks by their definition: greedily the best of `all` (ties to the first) apart from
// every earlier one, scoring above 0.
std::vector<Scored> greedy_peaks(const std::vector<Scored>& all, const LevelPoseGrid& g, double separation,
                                 double angle_separation) {
  std::vector<Scored> out;
  while (out.size() < 4) {
    const Scored* best = nullptr;
    for (const Scored& c : all) {
      const bool apart = std::all_of(out.begin(), out.end(), [&](const Scored& e) {
        return std::hypot(c.i - e.i, c.j - e.j) * g.step > separation ||
               std::abs(c.a - e.a) * g.angle_step > angle_separation;
      });
      if (apart && c.score > (best ? best->score : 0)) best = &c;
    }
    if (!best) break;
    out.push_back(*best);
  }
  return out;
}

TEST(LevelCoarseSearch, BranchAndBoundReturnsTheExhaustivePoseBitForBit) {
  const Scene& s = scene();
  const LevelPoseGrid base{2.0, 0.3, 0.4, 0.05};
  const NearOccupiedField field(s.map, level_bound_widths(base.step, s.map.grid().resolution()));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> off(-4.0, 4.0), turn(-0.5, 0.5), lift(-0.3, 0.3);
  int improved = 0;
  for (int k = 0; k < 12; ++k) {
    LevelPoseGrid g = base;
    g.radius = k % 3 == 0 ? 4.5 : 2.0;
    const Pose4 guess = s.truth.compose({off(rng), off(rng), lift(rng), turn(rng)});
    const LevelCoarseResult e = level_search_exhaustive(field, s.window.scored, guess, g);
    const LevelCoarseResult b = level_search_branch_and_bound(field, s.window.scored, guess, g);
    EXPECT_EQ(b.score, e.score) << k;
    EXPECT_EQ(b.pose.x, e.pose.x) << k;
    EXPECT_EQ(b.pose.y, e.pose.y) << k;
    EXPECT_EQ(b.pose.z, e.pose.z) << k;
    EXPECT_EQ(b.pose.yaw, e.pose.yaw) << k;
    improved += e.score > near_in_plane_count(field, guess, s.window.scored) ? 1 : 0;
  }
  EXPECT_GT(improved, 6);  // the searches did move off their guesses
  // Without the bound levels the branch and bound cannot run: a clear error, no fallback.
  const NearOccupiedField no_bounds(s.map);
  EXPECT_THROW(level_search_branch_and_bound(no_bounds, s.window.scored, s.truth, base), std::invalid_argument);
}

TEST(NearOccupiedField, BoundLevelsHoldWhetherAnyVoxelOfTheirBoxIsNearInThePlane) {
  const Scene& s = scene();
  const std::vector<int> widths{4, 7, 13};
  const NearOccupiedField field(s.map, widths);
  const OctreeGrid& grid = s.map.grid();
  const long cx = grid.axis_key(s.truth.x), cy = grid.axis_key(s.truth.y), cz = grid.axis_key(s.truth.z);
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<long> d(-60, 60), dz(-12, 12);
  int near = 0;
  for (int k = 0; k < 3000; ++k) {
    const long x = cx + d(rng), y = cy + d(rng), z = cz + dz(rng);
    for (std::size_t l = 1; l <= widths.size(); ++l) {
      bool any = false;
      for (long u = 0; u < widths[l - 1] && !any; ++u) {
        for (long v = 0; v < widths[l - 1] && !any; ++v) any = field.near_in_plane(0, x + u, y + v, z);
      }
      ASSERT_EQ(field.near_in_plane(l, x, y, z), any) << "level " << l << " at " << x - cx << ", " << y - cy;
      near += any ? 1 : 0;
    }
  }
  EXPECT_GT(near, 1000);
  // Level 0 is the point test.
  const Eigen::Vector3d p = s.truth.position() + Eigen::Vector3d(1.3, -0.7, -0.4);
  EXPECT_EQ(field.near_in_plane(0, grid.axis_key(p.x()), grid.axis_key(p.y()), grid.axis_key(p.z())),
            field.near_in_plane(p));
}

// The peaks of the wide re-entry search (its passes share their block scores) against their
// definition by brute force: every grid pose scored, then greedily the best (ties to the first
// in (yaw, x, y) order) apart from every earlier peak, scoring above 0.
TEST(LevelCoarseSearch, PeaksAreTheGreedyExhaustivePeaksBitForBit) {
  const Scene& s = scene();
  const NearOccupiedField field(s.map, level_bound_widths(0.3, s.map.grid().resolution()));
  const double separation = 1.5, angle_separation = 0.15;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> off(-3.0, 3.0), turn(-0.4, 0.4);
  for (int k = 0; k < 4; ++k) {
    const LevelPoseGrid g{k % 2 == 0 ? 3.0 : 2.4, 0.3, 0.3, 0.05};
    const Pose4 guess = s.truth.compose({off(rng), off(rng), 0.0, turn(rng)});
    const int n = static_cast<int>(g.radius / g.step), na = static_cast<int>(g.angle / g.angle_step);
    std::vector<Scored> all;
    for (int a = -na; a <= na; ++a) {
      for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
          const Pose4 p{guess.x + i * g.step, guess.y + j * g.step, guess.z,
                        normalize_angle(guess.yaw + a * g.angle_step)};
          all.push_back({a, i, j, near_in_plane_count(field, p, s.window.scored)});
        }
      }
    }
    const std::vector<Scored> expected = greedy_peaks(all, g, separation, angle_separation);
    const auto peaks = level_search_peaks(field, s.window.scored, guess, g, 4, separation, angle_separation);
    ASSERT_EQ(peaks.size(), expected.size()) << k;
    for (std::size_t m = 0; m < peaks.size(); ++m) {
      EXPECT_EQ(peaks[m].score, expected[m].score) << k << ", peak " << m;
      EXPECT_EQ(peaks[m].pose.x, guess.x + expected[m].i * g.step) << k << ", peak " << m;
      EXPECT_EQ(peaks[m].pose.y, guess.y + expected[m].j * g.step) << k << ", peak " << m;
      EXPECT_EQ(peaks[m].pose.yaw, normalize_angle(guess.yaw + expected[m].a * g.angle_step)) << k << ", peak " << m;
    }
  }
}

// The peaks of parts of one grid, searched together (the wide searches of several particles
// over one candidate), are each part's own greedy exhaustive peaks: every grid pose inside the
// part scored, the best apart from the earlier ones taken, as if the part were searched alone.
TEST(LevelCoarseSearch, PeaksWithinPartsAreEachPartsOwnGreedyPeaks) {
  const Scene& s = scene();
  const NearOccupiedField field(s.map, level_bound_widths(0.3, s.map.grid().resolution()));
  const double separation = 1.5, angle_separation = 0.15;
  const LevelPoseGrid g{3.6, 0.3, 0.35, 0.05};
  const Pose4 guess = s.truth.compose({1.1, -0.7, 0.0, 0.12});
  const std::vector<LevelSubgrid> parts{{guess.compose({-1.2, 0.6, 0.0, 0.0}), 1.8, 0.2},
                                        {guess.compose({1.5, -0.9, 0.0, 0.1}), 2.1, 0.15},
                                        {guess, g.radius, g.angle}};
  const auto found =
      level_search_peaks_within(field, s.window.scored, guess, g, parts, 4, separation, angle_separation);
  ASSERT_EQ(found.size(), parts.size());
  const int n = static_cast<int>(g.radius / g.step), na = static_cast<int>(g.angle / g.angle_step);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const LevelSubgrid& part = parts[k];
    std::vector<Scored> inside;
    for (int a = -na; a <= na; ++a) {
      for (int i = -n; i <= n; ++i) {
        for (int j = -n; j <= n; ++j) {
          const Pose4 p{guess.x + i * g.step, guess.y + j * g.step, guess.z,
                        normalize_angle(guess.yaw + a * g.angle_step)};
          if (std::abs(p.x - part.centre.x) > part.radius + 1e-9 ||
              std::abs(p.y - part.centre.y) > part.radius + 1e-9 ||
              std::abs(normalize_angle(p.yaw - part.centre.yaw)) > part.angle + 1e-9) {
            continue;
          }
          inside.push_back({a, i, j, near_in_plane_count(field, p, s.window.scored)});
        }
      }
    }
    const std::vector<Scored> expected = greedy_peaks(inside, g, separation, angle_separation);
    ASSERT_EQ(found[k].size(), expected.size()) << "part " << k;
    ASSERT_FALSE(expected.empty());
    for (std::size_t m = 0; m < expected.size(); ++m) {
      EXPECT_EQ(found[k][m].score, expected[m].score) << "part " << k << ", peak " << m;
      EXPECT_EQ(found[k][m].pose.x, guess.x + expected[m].i * g.step) << "part " << k << ", peak " << m;
      EXPECT_EQ(found[k][m].pose.y, guess.y + expected[m].j * g.step) << "part " << k << ", peak " << m;
    }
  }
  // The part spanning the grid is level_search_peaks.
  const auto whole = level_search_peaks(field, s.window.scored, guess, g, 4, separation, angle_separation);
  ASSERT_EQ(whole.size(), found[2].size());
  for (std::size_t m = 0; m < whole.size(); ++m) EXPECT_EQ(whole[m].pose.x, found[2][m].pose.x);
}

}  // namespace
}  // namespace lookahead::slam::segslam
