// SPDX-License-Identifier: MIT
// The evidence octree's kernels side by side with OctoMap 1.9 on the same rays: ray
// insertion, map copy, and the memory a particle map holds once its copies diverge.
// Scans are stationary half turns of the simulated spinning laser in the generated garage
// (1830 beams, 0.2 m voxels, 15 m insertion range), so one origin serves both libraries.
#include <benchmark/benchmark.h>
#include <octomap/OcTree.h>

#include <cmath>

#include "lookahead/slam/geometry/pose3.hpp"
#include "lookahead/slam/octree/octree_likelihood.hpp"
#include "lookahead/slam/octree/ray_insertion.hpp"
#include "lookahead/slam/sim3d/octree_ray_cast.hpp"
#include "lookahead/slam/sim3d/world3d.hpp"

namespace {

using namespace lookahead::slam;

constexpr double kMaxRange = 15.0;

const World3& garage() {
  static const World3 world = make_garage_world(1);
  return world;
}

/// A half turn of the spinning laser (30 lines x 61 beams) from a standing robot.
std::vector<Ray3> stationary_sweep(const Eigen::Vector3d& base, double yaw) {
  const Pose3 laser = make_pose3(base + Eigen::Vector3d(0, 0, 0.6), {0, 0, yaw});
  std::vector<Ray3> rays;
  for (int l = 0; l < 30; ++l) {
    const double phi = M_PI * l / 30.0;
    for (int b = 0; b < 61; ++b) {
      const double a = -M_PI / 2 + M_PI * b / 60.0;
      const Eigen::Vector3d dir =
          laser.linear() * Eigen::Vector3d(std::cos(a), std::sin(a) * std::cos(phi), std::sin(a) * std::sin(phi));
      const auto r = cast_ray(garage().map, laser.translation(), dir, 30.0);
      rays.push_back({laser.translation(), laser.translation() + dir * r.value_or(30.0), r.has_value()});
    }
  }
  return rays;
}

/// Sweeps one metre apart along the garage's first aisle.
const std::vector<std::vector<Ray3>>& sweeps() {
  static const std::vector<std::vector<Ray3>> all = [] {
    std::vector<std::vector<Ray3>> s;
    for (int i = 0; i < 40; ++i) s.push_back(stationary_sweep({8.0 + 0.3 * i, 7.0, 0.0}, 0.0));
    return s;
  }();
  return all;
}

octomap::Pointcloud cloud_of(const std::vector<Ray3>& rays) {
  octomap::Pointcloud c;
  for (const Ray3& r : rays)
    c.push_back(static_cast<float>(r.end.x()), static_cast<float>(r.end.y()), static_cast<float>(r.end.z()));
  return c;
}

octomap::point3d origin_of(const std::vector<Ray3>& rays) {
  const Eigen::Vector3d& o = rays.front().origin;
  return {static_cast<float>(o.x()), static_cast<float>(o.y()), static_cast<float>(o.z())};
}

EvidenceOctree map_after(int scans) {
  EvidenceOctree map;
  for (int i = 0; i < scans; ++i) insert_rays(map, sweeps()[static_cast<std::size_t>(i)], {kMaxRange});
  return map;
}

void BM_InsertSweep_Lookahead(benchmark::State& state) {
  EvidenceOctree map = map_after(10);
  std::size_t i = 10;
  for (auto _ : state) {
    insert_rays(map, sweeps()[i++ % sweeps().size()], {kMaxRange});
  }
  state.counters["rays/s"] =
      benchmark::Counter(1830.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_InsertSweep_Lookahead)->Unit(benchmark::kMillisecond);

void BM_InsertSweep_OctoMap(benchmark::State& state) {
  octomap::OcTree tree(0.2);
  for (int s = 0; s < 10; ++s)
    tree.insertPointCloud(cloud_of(sweeps()[static_cast<std::size_t>(s)]),
                          origin_of(sweeps()[static_cast<std::size_t>(s)]), kMaxRange);
  std::size_t i = 10;
  for (auto _ : state) {
    const auto& sweep = sweeps()[i++ % sweeps().size()];
    tree.insertPointCloud(cloud_of(sweep), origin_of(sweep), kMaxRange);
  }
  state.counters["rays/s"] =
      benchmark::Counter(1830.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_InsertSweep_OctoMap)->Unit(benchmark::kMillisecond);

/// The RBPF pattern: a resampled particle copies its parent's map, then inserts a sweep.
void BM_CopyThenInsert_Lookahead(benchmark::State& state) {
  const EvidenceOctree parent = map_after(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    EvidenceOctree child = parent;
    insert_rays(child, sweeps()[static_cast<std::size_t>(state.range(0))], {kMaxRange});
    benchmark::DoNotOptimize(child);
  }
}
BENCHMARK(BM_CopyThenInsert_Lookahead)->Arg(10)->Arg(39)->Unit(benchmark::kMillisecond);

void BM_Copy_Lookahead(benchmark::State& state) {
  const EvidenceOctree parent = map_after(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    EvidenceOctree child = parent;
    benchmark::DoNotOptimize(child);
  }
  state.counters["map_bytes"] = static_cast<double>(parent.memory().total_bytes);
}
BENCHMARK(BM_Copy_Lookahead)->Arg(10)->Arg(39);

void BM_Copy_OctoMap(benchmark::State& state) {
  octomap::OcTree tree(0.2);
  for (int s = 0; s < state.range(0); ++s)
    tree.insertPointCloud(cloud_of(sweeps()[static_cast<std::size_t>(s)]),
                          origin_of(sweeps()[static_cast<std::size_t>(s)]), kMaxRange);
  for (auto _ : state) {
    octomap::OcTree copy(tree);
    benchmark::DoNotOptimize(copy);
  }
  state.counters["map_bytes"] = static_cast<double>(tree.memoryUsage());
}
BENCHMARK(BM_Copy_OctoMap)->Arg(10)->Arg(39)->Unit(benchmark::kMillisecond);

/// Scoring one particle: 610 end points (every third beam), 27 voxels each.
void BM_Likelihood_Lookahead(benchmark::State& state) {
  const EvidenceOctree map = map_after(39);
  std::vector<Eigen::Vector3d> ends;
  const auto& sweep = sweeps()[20];
  for (std::size_t i = 0; i < sweep.size(); i += 3) {
    if (sweep[i].hit) ends.push_back(sweep[i].end + Eigen::Vector3d(0.05, -0.03, 0.02));
  }
  for (auto _ : state) benchmark::DoNotOptimize(octree_log_likelihood(map, ends, {}));
  state.counters["end_points"] = static_cast<double>(ends.size());
}
BENCHMARK(BM_Likelihood_Lookahead)->Unit(benchmark::kMicrosecond);

/// Memory of a particle population: N copies of a map after `scans` sweeps, each then
/// inserting its own (shifted) sweep, as after a resampling. Counters in bytes.
void BM_ParticleMemory_Lookahead(benchmark::State& state) {
  const int scans = static_cast<int>(state.range(0));
  const int particles = 20;
  const EvidenceOctree parent = map_after(scans);
  std::vector<EvidenceOctree> maps;
  for (auto _ : state) {
    maps.assign(static_cast<std::size_t>(particles), parent);
    for (int p = 0; p < particles; ++p) {
      std::vector<Ray3> rays = sweeps()[static_cast<std::size_t>(scans)];
      for (Ray3& r : rays) r.end += Eigen::Vector3d(0.01 * p, 0.0, 0.0);
      insert_rays(maps[static_cast<std::size_t>(p)], rays, {kMaxRange});
    }
  }
  double unique = 0;
  std::vector<const EvidenceOctree*> all;
  for (const auto& m : maps) {
    unique += static_cast<double>(m.memory().unique_bytes);
    all.push_back(&m);
  }
  state.counters["full_map_bytes"] = static_cast<double>(maps.front().memory().total_bytes);
  state.counters["unique_bytes_per_particle"] = unique / particles;
  state.counters["all_20_maps_bytes"] = static_cast<double>(EvidenceOctree::distinct_bytes(all));
}
BENCHMARK(BM_ParticleMemory_Lookahead)->Arg(10)->Arg(39)->Iterations(3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
