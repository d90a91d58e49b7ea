// SPDX-License-Identifier: MIT
// One simulated LMS-200 scan (181 beams, 1 deg, 8 m) on real floor plans: how many scans per
// second the simulator can produce, which bounds how fast a mission can run.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "lookahead/exploration/laser_simulator.hpp"
#include "lookahead/exploration/robot.hpp"
#include "lookahead/exploration/world_loader.hpp"

namespace {

using lookahead::exploration::World;

const std::string kPlans = std::string(LOOKAHEAD_SHARED_DIR) + "/data/floorplans/";

// Seeded poses where the Pioneer disc fits, so every scan starts in free space.
std::vector<lookahead::slam::Pose2> free_poses(const World& w, int n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> ux(w.origin().x(), w.origin().x() + w.width_m());
  std::uniform_real_distribution<double> uy(w.origin().y(), w.origin().y() + w.height_m());
  std::uniform_real_distribution<double> ut(-M_PI, M_PI);
  std::vector<lookahead::slam::Pose2> poses;
  while (static_cast<int>(poses.size()) < n) {
    const lookahead::slam::Pose2 p{ux(rng), uy(rng), ut(rng)};
    if (!lookahead::exploration::disc_collides(w, {p.x, p.y}, 0.25)) poses.push_back(p);
  }
  return poses;
}

void run_scans(benchmark::State& state, const World& world) {
  lookahead::exploration::LaserSimulator laser(world);
  const auto poses = free_poses(world, 256);
  std::size_t i = 0;
  for (auto _ : state) {
    auto scan = laser.scan(poses[i++ % poses.size()], 0.0);
    benchmark::DoNotOptimize(scan.ranges.data());
  }
  state.counters["scans/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["beams"] = static_cast<double>(laser.options().beam_count());
}

// Stage's hospital section: 40 m x 18 m of small rooms at 3.7 cm cells.
void BM_ScanHospitalSection(benchmark::State& state) {
  static const World world = lookahead::exploration::load_stage_world(kPlans + "stage/worlds/everything.world");
  run_scans(state, world);
}
BENCHMARK(BM_ScanHospitalSection);

// Intel lab SLAM grid (0.05 m assumed, map_server values): long open corridors.
void BM_ScanIntel(benchmark::State& state) {
  static const World world = lookahead::exploration::load_image_world(
      kPlans + "mrgs_compression_benchmark/intel.pgm",
      {0.05, {0.0, 0.0}, lookahead::exploration::PixelRule::map_server(0.196, false)});
  run_scans(state, world);
}
BENCHMARK(BM_ScanIntel);

}  // namespace

BENCHMARK_MAIN();
