// SPDX-License-Identifier: MIT
// Test data shared by the SegSLAM 3D tests: a short simulated garage drive, maps and matching
// windows built from its true poses.
#pragma once

#include <cstddef>
#include <vector>

#include "lookahead/slam/octree/ray_insertion.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/sim3d/cave_crawler_sim.hpp"

namespace lookahead::slam::segslam::test_data {

/// The first 21 m of the garage loop (world seed 1), simulated once per test binary.
inline const RangeLog3& garage_log() {
  static const RangeLog3 log = [] {
    World3 w = make_garage_world(1, 0.2);
    w.route.resize(3);
    return simulate_cave_crawler(w, {}, 1);
  }();
  return log;
}

/// Along the garage's first aisle and back, twice (66 sweeps): the later legs re-enter the
/// first legs' submaps.
inline const RangeLog3& aisle_back_and_forth() {
  static const RangeLog3 log = [] {
    World3 w = make_garage_world(1, 0.2);
    const Eigen::Vector3d a{8, 7, 0}, b{20, 7, 0};
    w.route = {a, b, a, b, a};
    return simulate_cave_crawler(w, {}, 2);
  }();
  return log;
}

/// SegSLAM 3D options for aisle_back_and_forth(): `particles` on both cores, filter seed 3,
/// segments of at least 5 sweeps, candidates 15 s old (the legs are about 12 s long).
inline SegSlam3dOptions aisle_options(int particles) {
  SegSlam3dOptions o;
  o.filter.particles = particles;
  o.filter.threads = 2;
  o.filter.seed = 3;
  o.segslam.segmentation.min_segment_updates = 5;
  o.segslam.segmentation.max_motion_error = 0.2;
  o.segslam.matching.min_separation_s = 15;
  return o;
}

/// Every sweep of `log` through `filter`, then the updates still waiting for their window.
inline void run_filter(SegSlam3d& filter, const RangeLog3& log) {
  for (const RangeSweep& s : log.sweeps) filter.add_sweep(s);
  filter.finish();
}

/// A map of sweeps [first, last] inserted at their true poses, in the world frame.
inline EvidenceOctree map_of(const RangeLog3& log, std::size_t first, std::size_t last) {
  EvidenceOctree map;
  for (std::size_t i = first; i <= last; ++i) {
    std::vector<Ray3> rays;
    const Pose3& t = *log.sweeps[i].truth;
    for (const Ray3& r : log.sweeps[i].rays) rays.push_back({t * r.origin, t * r.end, r.hit});
    insert_rays(map, rays, {});
  }
  return map;
}

/// The end points of sweeps [first, last] in the true level frame of the robot at `first`.
inline SweepWindow window_of(const RangeLog3& log, std::size_t first, std::size_t last) {
  const Pose3 to_start = Pose4::level_of(*log.sweeps[first].truth).level_pose3().inverse();
  Points3 all;
  for (std::size_t i = first; i <= last; ++i) {
    for (const Ray3& r : log.sweeps[i].rays) {
      if (r.hit && (r.end - r.origin).norm() < 15.0) all.push_back(to_start * (*log.sweeps[i].truth * r.end));
    }
  }
  return make_sweep_window(all, 300, segslam3d_defaults().matching);
}

}  // namespace lookahead::slam::segslam::test_data
