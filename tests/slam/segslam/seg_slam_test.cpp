// SPDX-License-Identifier: MIT
// SegSLAM end to end on the polygonal test room, and the copy-on-write and entropy pieces
// it relies on.
#include "lookahead/slam/segslam/seg_slam.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../test_world.hpp"
#include "candidate_reach.hpp"
#include "lookahead/slam/segslam/min_entropy_search.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::slam::segslam {
namespace {

// Twice around the inner box of the test room, with odometry drifting in heading.
std::vector<std::pair<Pose2, LaserScan>> two_loops() {
  const auto world = test::room_world();
  std::vector<std::pair<Pose2, LaserScan>> out;
  Pose2 truth{1.5, 1.0, 0.0}, odom = truth;
  const std::vector<Pose2> legs{{7.0, 0, 0}, {0, 0, M_PI / 2}, {4.0, 0, 0}, {0, 0, M_PI / 2},
                                {7.0, 0, 0}, {0, 0, M_PI / 2}, {4.0, 0, 0}, {0, 0, M_PI / 2}};
  double t = 0;
  for (int loop = 0; loop < 2; ++loop) {
    for (const Pose2& leg : legs) {
      const int steps = leg.x > 0 ? static_cast<int>(leg.x / 0.1) : 10;
      for (int i = 0; i < steps; ++i) {
        const Pose2 step{leg.x / steps, 0, leg.theta / steps};
        truth = truth.compose(step);
        odom = odom.compose({step.x, 0, step.theta + step.x * 0.03});  // 1.7 deg/m bias
        out.push_back({truth, test::simulate_scan(world, truth, odom, t += 0.2)});
      }
    }
  }
  return out;
}

// Three particles, short segments and a short temporal separation: the test room's scale.
RbpfOptions room_rbpf() {
  RbpfOptions rbpf;
  rbpf.particles = 3;
  rbpf.threads = 1;
  rbpf.linear_update = 0.3;
  return rbpf;
}

SegSlamOptions room_options() {
  SegSlamOptions o;
  o.segmentation.min_segment_updates = 6;
  o.segmentation.max_motion_error = 0.4;
  o.matching.min_separation_s = 10;
  return o;
}

void feed(SegSlam& filter, const std::vector<std::pair<Pose2, LaserScan>>& data) {
  for (const auto& d : data) filter.add_scan(d.second);
  filter.finish();
}

TEST(SegSlam, SegmentsMatchesAndClosesTheLoop) {
  SegSlam filter(room_rbpf(), room_options());
  const auto data = two_loops();
  feed(filter, data);
  EXPECT_GT(filter.statistics().segmentations, 2u);
  EXPECT_GT(filter.statistics().matches, 0u);
  const Pose2 truth = data.back().first, odom = data.back().second.odometry;
  const Pose2 est = filter.estimate();
  const double odom_error = std::hypot(odom.x - truth.x, odom.y - truth.y);
  EXPECT_LT(std::hypot(est.x - truth.x, est.y - truth.y), 0.3 * odom_error);
  // Every scan gets a pose, and the offline search returns its least-entropy sample.
  EXPECT_EQ(filter.trajectory_at_every_scan(0).size(), data.size());
  const MinEntropyResult r = min_entropy_search(filter, 4, 1, 1);
  for (double h : r.entropies) EXPECT_LE(r.best.entropy, h);
  // The picture's path is the sample's: every placed submap's own path, in its sample frame,
  // in time order, and an X per placed re-entry.
  const SegmentedPath paths = sample_paths(filter, r.best);
  ASSERT_EQ(paths.pieces.size(), r.best.placed.size());
  std::size_t reentries = 0, poses = 0;
  for (std::size_t i = 0; i < r.best.placed.size(); ++i) {
    const GridSubmap& m =
        i == 0 ? filter.particles().at(r.best.particle).submap : filter.segmap().at(r.best.placed[i].id);
    reentries += m.parent != kNoSubmap ? 1 : 0;
    poses += m.path.size();
  }
  EXPECT_EQ(paths.matches.size(), reentries);
  std::size_t drawn = 0;
  for (const auto& piece : paths.pieces) drawn += piece.size();
  EXPECT_EQ(drawn, poses);
  const Pose2 start = r.best.placed[0].frame.compose(filter.particles().at(r.best.particle).submap.path.front().second);
  bool found = false;
  for (const auto& piece : paths.pieces) found = found || (piece.front().x == start.x && piece.front().y == start.y);
  EXPECT_TRUE(found) << "the start submap's path, placed by the sample";
}

// The best particle's own chain as a map (offline.particle_chain): its path is the
// particle's eq. 11 trajectory, and the search returns it only where its entropy is least.
TEST(SegSlam, TheParticleChainMapFollowsTheParticlesTrajectory) {
  SegSlam filter(room_rbpf(), room_options());
  feed(filter, two_loops());
  ASSERT_GT(filter.statistics().matches, 0u);
  const std::size_t best = filter.best_particle();
  const MapSample chain = particle_chain_sample(filter, best);
  EXPECT_TRUE(chain.chain);
  std::size_t length = 1;
  for (std::size_t id = filter.particles()[best].submap.predecessor; id != kNoSubmap;
       id = filter.segmap().at(id).predecessor) {
    ++length;
  }
  EXPECT_EQ(chain.placed.size(), length);
  const std::vector<Pose2> path = sample_trajectory_at_every_scan(filter, chain);
  const std::vector<Pose2> trajectory = filter.trajectory_at_every_scan(best);
  ASSERT_EQ(path.size(), trajectory.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    ASSERT_NEAR(path[i].x, trajectory[i].x, 1e-9) << "scan " << i;
    ASSERT_NEAR(path[i].y, trajectory[i].y, 1e-9) << "scan " << i;
    ASSERT_NEAR(normalize_angle(path[i].theta - trajectory[i].theta), 0.0, 1e-9) << "scan " << i;
  }
  const MinEntropyResult with = min_entropy_search(filter, 4, 1, 1);
  EXPECT_NEAR(with.chain_entropy, chain.entropy, 1e-9);
  EXPECT_LE(with.best.entropy, with.chain_entropy);
  for (double h : with.entropies) EXPECT_LE(with.best.entropy, h);
  EXPECT_EQ(with.best.chain, with.chain_entropy < *std::min_element(with.entropies.begin(), with.entropies.end()));
  // No samples: the chain is the map.
  const MinEntropyResult alone = min_entropy_search(filter, 0, 1, 1);
  EXPECT_TRUE(alone.best.chain);
  EXPECT_TRUE(alone.entropies.empty());
  EXPECT_NEAR(alone.best.entropy, chain.entropy, 1e-9);
  // Off: the breadth-first samples only, as the paper searches.
  SegSlamOptions off = room_options();
  off.offline.particle_chain = false;
  SegSlam without(room_rbpf(), off);
  feed(without, two_loops());
  const MinEntropyResult r = min_entropy_search(without, 4, 1, 1);
  EXPECT_FALSE(r.best.chain);
  EXPECT_EQ(r.chain_entropy, 0.0);
}

// Sec. 4.4: a match child is a copy of its parent that stores only its changes.
TEST(SegSlam, CopyOnWriteChildStoresOnlyItsChanges) {
  const auto world = test::room_world();
  OccupancyGrid parent;
  for (double x = 1; x < 9; x += 0.5) insert_scan(parent, {x, 1, 0}, test::simulate_scan(world, {x, 1, 0}, {}), {});
  OccupancyGrid child = parent;
  EXPECT_EQ(child.tiles_shared_with(parent), parent.tile_count());
  InsertOptions short_range;  // a scan that sees a corner of the room only
  short_range.max_usable_range = 1.5;
  insert_scan(child, {8.5, 5.0, M_PI}, test::simulate_scan(world, {8.5, 5.0, M_PI}, {}), short_range);
  const std::size_t changed = child.tile_count() - child.tiles_shared_with(parent);
  EXPECT_GT(changed, 0u);
  EXPECT_LT(changed, parent.tile_count() / 2);
  // Pasting the child after its parent adds only those tiles' changes.
  MapCanvas with_parent(0.05, -2, 3.5), alone(0.05, -2, 3.5);
  with_parent.paste(parent, {});
  with_parent.paste(child, {}, &parent);
  alone.paste(child, {});
  EXPECT_NEAR(scaled_entropy(with_parent.to_probability_map()), scaled_entropy(alone.to_probability_map()),
              0.02 * scaled_entropy(alone.to_probability_map()));
}

// Eq. 20-22: of two samples of the same submaps, the registered one has less entropy, so
// the minimum-entropy search prefers it.
TEST(SegSlam, RegisteredSampleHasLessEntropy) {
  const auto world = test::room_world();
  OccupancyGrid a, b;
  insert_scan(a, {2, 1, 0.3}, test::simulate_scan(world, {2, 1, 0.3}, {}), {});
  insert_scan(b, {0, 0, 0}, test::simulate_scan(world, {2.5, 1.2, 0.5}, {}), {});  // b's frame: its start
  MapCanvas good(0.05, -2, 3.5), bad(0.05, -2, 3.5);
  good.paste(a, {}), good.paste(b, {2.5, 1.2, 0.5});
  bad.paste(a, {}), bad.paste(b, {2.9, 1.0, 0.55});
  EXPECT_LT(scaled_entropy(good.to_probability_map()), scaled_entropy(bad.to_probability_map()));
}

}  // namespace
}  // namespace lookahead::slam::segslam

namespace lookahead::slam::segslam {
namespace {

// Determinism: the match cache and the parallel particle loop do not change the result.
TEST(SegSlam, SameSeedSameResultWhateverTheThreadCount) {
  const auto data = two_loops();
  Pose2 est[2];
  for (int threads = 1; threads <= 2; ++threads) {
    RbpfOptions rbpf;
    rbpf.particles = 4;
    rbpf.threads = threads;
    rbpf.linear_update = 0.3;
    SegSlamOptions o;
    o.segmentation.min_segment_updates = 6;
    o.matching.min_separation_s = 10;
    SegSlam filter(rbpf, o);
    for (std::size_t i = 0; i < data.size() / 2; ++i) filter.add_scan(data[i].second);
    filter.finish();
    est[threads - 1] = filter.estimate();
  }
  EXPECT_EQ(est[0].x, est[1].x);
  EXPECT_EQ(est[0].y, est[1].y);
  EXPECT_EQ(est[0].theta, est[1].theta);
}

}  // namespace
}  // namespace lookahead::slam::segslam

namespace lookahead::slam::segslam {
namespace {

// The room mapped along y = 1, and a window of four scans seen from `truth` onwards.
OccupancyGrid room_corridor_map() {
  const auto world = test::room_world();
  OccupancyGrid map;
  for (double x = 1.5; x < 8.5; x += 0.5)
    insert_scan(map, {x, 1.0, 0}, test::simulate_scan(world, {x, 1.0, 0}, {}), {});
  return map;
}

LookaheadWindow window_from(const Pose2& truth) {
  const auto world = test::room_world();
  LookaheadWindow w;
  Points2 points;
  for (int k = 0; k < 4; ++k) {
    const Pose2 rel{0.3 * k, 0, 0};
    const LaserScan s = test::simulate_scan(world, truth.compose(rel), {});
    w.scans.push_back(prepare_scan(s, LikelihoodOptions{}));
    w.relative_poses.push_back(rel);
    for (std::size_t b = 0; b < s.ranges.size(); ++b) {
      if (!std::isfinite(s.ranges[b])) continue;
      const Pose2 end = rel.compose({s.ranges[b] * std::cos(s.bearing(b)), s.ranges[b] * std::sin(s.bearing(b)), 0});
      points.emplace_back(end.x, end.y);
    }
  }
  w.cloud = bin_points(points, 0.1);
  return w;
}

// The 2D filter's candidate reach (candidate_reach.hpp): a guess 4.5 m off is beyond the fixed
// 2 m search, within the reach widened by 5 m of eq. 13-14 error; one match target, built for
// the widest reach (as SegSlam builds it), serves both searches.
TEST(SegSlam, TheWidenedReachFindsAGuessBeyondTheFixedSearch) {
  const OccupancyGrid map = room_corridor_map();
  const Pose2 truth{2.5, 1.0, 0.0};
  const LookaheadWindow w = window_from(truth);
  const LikelihoodFieldModel likelihood(LikelihoodOptions{}, map);
  MatchingOptions fixed;
  fixed.icp_iterations = 3;  // the coarse search decides: ICP alone slides far along this room's walls
  MatchingOptions widest = fixed;
  widest.search_radius = fixed.max_search_radius;
  const GridMatchTarget target = match_target_of(map, widest, likelihood);
  const Pose2 guess{7.0, 1.3, 0.05};
  const auto at_truth = [&](const WindowMatch& m) {
    return m.ok && std::hypot(m.pose.x - truth.x, m.pose.y - truth.y) < 0.1 && std::abs(m.pose.theta) < 0.05;
  };
  EXPECT_FALSE(at_truth(match_window(map, target, w, guess, fixed)));
  const MatchingOptions reach = candidate_reach(fixed, 5.0, fixed.max_search_radius);
  ASSERT_GT(reach.search_radius, 4.6);
  const WindowMatch wide = match_window(map, target, w, guess, reach);
  EXPECT_TRUE(at_truth(wide)) << wide.pose.x << " " << wide.pose.y << " " << wide.pose.theta;
  EXPECT_GT(wide.weight, 0.0);  // eq. 18's sigma_tau widened with the reach
}

// Sec. 4.5: both matchers bring a window seen from a known pose back onto the map from a
// guess 0.4 m and 0.1 rad off.
TEST(SegSlam, BothMatchersRecoverTheWindowPose) {
  const OccupancyGrid map = room_corridor_map();
  const Pose2 truth{4.0, 1.0, 0.0};
  const LookaheadWindow w = window_from(truth);
  const LikelihoodFieldModel likelihood(LikelihoodOptions{}, map);
  MatchingOptions o;
  const Pose2 guess{4.3, 1.25, 0.1};
  const WindowMatch icp = match_window(map, match_target_of(map, o, likelihood), w, guess, o);
  const WindowMatch loc = localize_window(map, w, guess, o, likelihood, 3);
  for (const WindowMatch& m : {icp, loc}) {
    EXPECT_TRUE(m.ok);
    EXPECT_NEAR(m.pose.x, truth.x, 0.1);
    EXPECT_NEAR(m.pose.y, truth.y, 0.1);
    EXPECT_NEAR(m.pose.theta, truth.theta, 0.05);
    EXPECT_GT(m.weight, 0.0);
  }
}

}  // namespace
}  // namespace lookahead::slam::segslam
