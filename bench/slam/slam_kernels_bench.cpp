// SPDX-License-Identifier: MIT
// Hot loops of the RBPF, side by side with MRPT's occupancy grid (the map behind MRPT's
// rbpf-slam) doing the same work on the same real scans (fr101, first 150 scans placed by
// odometry): ray-cast insertion, likelihood-field evaluation, map copy; plus our scan
// matcher and improved proposal. Run with --benchmark_repetitions=5 and read the medians.
#include <benchmark/benchmark.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <random>

#include "lookahead/slam/io/laser_log.hpp"
#include "lookahead/slam/rbpf/improved_proposal.hpp"
#include "lookahead/slam/rbpf/scan_matcher.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace {

using namespace lookahead::slam;

constexpr std::size_t kMapScans = 150;
constexpr double kUsableRange = 30.0;

struct Fixture {
  LaserLog log;
  OccupancyGrid grid;
  mrpt::maps::COccupancyGridMap2D mrpt_grid{-50, 50, -50, 50, 0.05f};
  std::vector<mrpt::obs::CObservation2DRangeScan> mrpt_scans;
  LaserScan probe;  // the next scan after the map ones

  Fixture() {
    log = read_carmen_log(LOOKAHEAD_SHARED_DIR "/data/fr101/fr101.carmen.log");
    mrpt_grid.insertionOptions.maxDistanceInsertion = static_cast<float>(kUsableRange);
    mrpt_grid.likelihoodOptions.likelihoodMethod = mrpt::maps::COccupancyGridMap2D::lmLikelihoodField_Thrun;
    mrpt_grid.likelihoodOptions.LF_decimation = 2;  // our beam_step
    for (std::size_t i = 0; i <= kMapScans; ++i) mrpt_scans.push_back(to_mrpt(log.scans[i]));
    for (std::size_t i = 0; i < kMapScans; ++i) {
      insert_scan(grid, log.scans[i].odometry, log.scans[i], {kUsableRange});
      mrpt_grid.insertObservation(mrpt_scans[i], pose3d(log.scans[i].odometry));
    }
    probe = log.scans[kMapScans];
  }

  static mrpt::poses::CPose3D pose3d(const Pose2& p) { return {p.x, p.y, 0.0, p.theta, 0.0, 0.0}; }

  static mrpt::obs::CObservation2DRangeScan to_mrpt(const LaserScan& s) {
    mrpt::obs::CObservation2DRangeScan o;
    o.aperture = static_cast<float>(s.angle_increment * static_cast<double>(s.ranges.size() - 1));
    o.rightToLeft = true;
    o.maxRange = static_cast<float>(s.max_range);
    o.sensorPose = pose3d(s.laser_offset);
    o.resizeScan(s.ranges.size());
    for (std::size_t i = 0; i < s.ranges.size(); ++i) {
      o.setScanRange(i, s.is_return(i) ? s.ranges[i] : 0.0f);
      o.setScanRangeValidity(i, s.is_return(i));
    }
    return o;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

// ---- ray-cast insertion ----
void BM_InsertScan_Lookahead(benchmark::State& state) {
  auto& f = fixture();
  for (auto _ : state) {
    OccupancyGrid g = f.grid;  // shared tiles: the insertion pays the copy-on-write of what it touches
    insert_scan(g, f.probe.odometry, f.probe, {kUsableRange});
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_InsertScan_Lookahead)->Unit(benchmark::kMicrosecond);

// The same scan traced point to point (InsertOptions::exact_rays, the exploration default).
void BM_InsertScan_Lookahead_ExactRays(benchmark::State& state) {
  auto& f = fixture();
  InsertOptions exact{kUsableRange};
  exact.exact_rays = true;
  for (auto _ : state) {
    OccupancyGrid g = f.grid;
    insert_scan(g, f.probe.odometry, f.probe, exact);
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_InsertScan_Lookahead_ExactRays)->Unit(benchmark::kMicrosecond);

void BM_InsertScan_Mrpt(benchmark::State& state) {
  auto& f = fixture();
  const auto obs = f.mrpt_scans[kMapScans];
  for (auto _ : state) {
    state.PauseTiming();
    mrpt::maps::COccupancyGridMap2D g = f.mrpt_grid;  // MRPT has no sharing: copy outside the timing
    state.ResumeTiming();
    g.insertObservation(obs, Fixture::pose3d(f.probe.odometry));
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_InsertScan_Mrpt)->Unit(benchmark::kMicrosecond);

// ---- likelihood field ----
void BM_Likelihood_Lookahead(benchmark::State& state) {
  auto& f = fixture();
  const LikelihoodFieldModel model(LikelihoodOptions{}, f.grid);
  const PreparedScan scan = prepare_scan(f.probe, LikelihoodOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(model.log_likelihood(f.grid, f.probe.odometry, scan));
  state.counters["beams"] = static_cast<double>(scan.x.size());
}
BENCHMARK(BM_Likelihood_Lookahead);

// The bilinear lookup the scans between updates are tracked with: four reads per end point.
void BM_Likelihood_Lookahead_Bilinear(benchmark::State& state) {
  auto& f = fixture();
  const LikelihoodFieldModel model(LikelihoodOptions{}, f.grid);
  const PreparedScan scan = prepare_scan(f.probe, LikelihoodOptions{});
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.log_likelihood(f.grid, f.probe.odometry, scan, FieldLookup::kBilinear));
  }
  state.counters["beams"] = static_cast<double>(scan.x.size());
}
BENCHMARK(BM_Likelihood_Lookahead_Bilinear);

void BM_Likelihood_Mrpt(benchmark::State& state) {
  auto& f = fixture();
  const auto& obs = f.mrpt_scans[kMapScans];
  const auto pose = Fixture::pose3d(f.probe.odometry);
  f.mrpt_grid.computeObservationLikelihood(obs, pose);  // builds MRPT's cached field once
  for (auto _ : state) benchmark::DoNotOptimize(f.mrpt_grid.computeObservationLikelihood(obs, pose));
}
BENCHMARK(BM_Likelihood_Mrpt);

// ---- map copy (what resampling pays per particle) ----
void BM_MapCopy_Lookahead(benchmark::State& state) {
  auto& f = fixture();
  for (auto _ : state) {
    OccupancyGrid g = f.grid;
    benchmark::DoNotOptimize(g);
  }
  state.counters["tiles"] = static_cast<double>(f.grid.tile_count());
}
BENCHMARK(BM_MapCopy_Lookahead)->Unit(benchmark::kMicrosecond);

void BM_MapCopy_Mrpt(benchmark::State& state) {
  auto& f = fixture();
  for (auto _ : state) {
    mrpt::maps::COccupancyGridMap2D g = f.mrpt_grid;
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(BM_MapCopy_Mrpt)->Unit(benchmark::kMicrosecond);

// ---- our scan matcher and improved proposal (one particle's update) ----
void BM_ScanMatch_Lookahead(benchmark::State& state) {
  auto& f = fixture();
  const LikelihoodFieldModel model(LikelihoodOptions{}, f.grid);
  const ScanMatcher matcher(ScanMatcherOptions{}, model);
  const PreparedScan scan = prepare_scan(f.probe, LikelihoodOptions{});
  const Pose2 start{f.probe.odometry.x + 0.1, f.probe.odometry.y - 0.08, f.probe.odometry.theta + 0.03};
  int evaluations = 0;
  for (auto _ : state) {
    const MatchResult r = matcher.match(f.grid, start, scan);
    evaluations = r.evaluations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_ScanMatch_Lookahead)->Unit(benchmark::kMicrosecond);

void BM_ImprovedProposal_Lookahead(benchmark::State& state) {
  auto& f = fixture();
  const LikelihoodFieldModel model(LikelihoodOptions{}, f.grid);
  const OdometryMotionModel motion;
  const PreparedScan scan = prepare_scan(f.probe, LikelihoodOptions{});
  const Pose2 previous = f.log.scans[kMapScans - 3].odometry;
  const Pose2 u = previous.between(f.probe.odometry);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        improved_proposal(f.grid, previous, u, f.probe.odometry, scan, model, motion, {}, FieldLookup::kBilinear));
  }
}
BENCHMARK(BM_ImprovedProposal_Lookahead)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
