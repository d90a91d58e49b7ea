// SPDX-License-Identifier: MIT
// Planner kernels on a generated 20 m x 15 m office (5 cm cells, 3 x 2 rooms joined by
// 0.9 m doors): costmap construction (raster + exact distance transform; on an 80 m x 45 m
// building also the update of a laser's window against a rebuild), the cell-walk
// segment check OMPL calls for every edge, and whole plan() calls per algorithm with a fixed
// sample count (so every run does the same work; time_budget is only a safety cap).
// Run with --benchmark_repetitions=5 and read the medians.
#include <benchmark/benchmark.h>

#include <random>

#include "lookahead/planner/costmap.hpp"
#include "lookahead/planner/ompl_logging.hpp"
#include "lookahead/planner/plan.hpp"

namespace {

using namespace lookahead;
using planner::PlannerAlgorithm;

/// Occupied: three hits (p ~ 0.93). Free: misses until p <= 0.40, so a door can be cut
/// into a wall drawn before it.
void fill(slam::OccupancyGrid& g, int x0, int y0, int x1, int y1, bool occupied) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (occupied) {
        for (int i = 0; i < 3; ++i) g.add_log_odds({x, y}, g.fixed_hit());
        continue;
      }
      do {
        g.add_log_odds({x, y}, g.fixed_miss());
      } while (g.raw_log_odds({x, y}) > g.fixed_miss());
    }
  }
}

/// 400 x 300 cells; inner walls at x = 133, 266 and y = 150, each with a door per room.
slam::OccupancyGrid office() {
  slam::OccupancyGrid g;
  fill(g, 0, 0, 399, 299, false);
  fill(g, -2, -2, 401, -1, true);
  fill(g, -2, 300, 401, 301, true);
  fill(g, -2, -2, -1, 301, true);
  fill(g, 400, -2, 401, 301, true);
  for (const int x : {133, 266}) {
    fill(g, x, 0, x + 2, 299, true);
    fill(g, x, 60, x + 2, 77, false);  // doors 0.9 m wide
    fill(g, x, 210, x + 2, 227, false);
  }
  fill(g, 0, 150, 399, 152, true);
  for (const int x : {60, 190, 320}) fill(g, x, 150, x + 17, 152, false);
  return g;
}

const slam::OccupancyGrid& shared_office() {
  static const slam::OccupancyGrid g = office();
  return g;
}

void BM_CostmapBuild(benchmark::State& state) {
  const slam::OccupancyGrid& g = shared_office();
  for (auto _ : state) {
    planner::Costmap c(g, {});
    benchmark::DoNotOptimize(c);
  }
  state.counters["cells"] = 404.0 * 304.0;
}
BENCHMARK(BM_CostmapBuild)->Unit(benchmark::kMillisecond);

/// 80 m x 45 m: the office's rooms repeated 4 x 3 times, the size of a large KTH plan.
const slam::OccupancyGrid& shared_building() {
  static const slam::OccupancyGrid g = [] {
    slam::OccupancyGrid b;
    fill(b, 0, 0, 1599, 899, false);
    for (int x = 0; x <= 1600; x += 133) {
      fill(b, x, 0, x + 2, 899, true);
      for (int y = 60; y < 900; y += 150) fill(b, x, y, x + 2, y + 17, false);  // 0.9 m doors
    }
    for (int y = 0; y <= 900; y += 150) {
      fill(b, 0, y, 1599, y + 2, true);
      for (int x = 60; x < 1600; x += 133) fill(b, x, y, x + 17, y + 2, false);
    }
    return b;
  }();
  return g;
}

// A mission's refresh after a scan, the old way: the whole raster again.
void BM_CostmapRebuildLarge(benchmark::State& state) {
  const slam::OccupancyGrid& g = shared_building();
  for (auto _ : state) {
    planner::Costmap c(g, {});
    benchmark::DoNotOptimize(c);
  }
}
BENCHMARK(BM_CostmapRebuildLarge)->Unit(benchmark::kMillisecond);

// The same refresh as an update of the window a 12 m laser reaches (plus 1 m) around the
// middle of the building: the raster a rebuild gives, at the cost of the window.
void BM_CostmapUpdateWindowLarge(benchmark::State& state) {
  const slam::OccupancyGrid& g = shared_building();
  planner::Costmap c(g, {});
  const int r = 260;  // 13 m in 5 cm cells
  for (auto _ : state) {
    c.update(g, {800 - r, 450 - r}, {800 + r, 450 + r});
    benchmark::DoNotOptimize(c);
  }
}
BENCHMARK(BM_CostmapUpdateWindowLarge)->Unit(benchmark::kMillisecond);

void BM_SegmentIsFree(benchmark::State& state) {
  const planner::Costmap c(shared_office(), {});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> x(0.0, 20.0), y(0.0, 15.0);
  std::vector<planner::Point2> ends(2048);
  for (auto& p : ends) p = {x(rng), y(rng)};
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.segment_is_free(ends[i % 2048], ends[(i + 1) % 2048]));
    ++i;
  }
}
BENCHMARK(BM_SegmentIsFree);

void BM_Plan(benchmark::State& state) {
  planner::set_ompl_log_level(planner::OmplLogLevel::kWarn);
  const planner::Costmap c(shared_office(), {});
  planner::PlannerOptions o;
  o.algorithm = static_cast<PlannerAlgorithm>(state.range(0));
  o.max_samples = state.range(1);
  o.time_budget = 30.0;
  double length = 0.0;
  std::size_t solved = 0;
  for (auto _ : state) {
    // From the lower-left room to the upper-right one: two doors at least.
    const planner::PlanResult r = planner::plan(c, slam::Pose2{1.0, 1.0, 0.0}, 19.0, 14.0, o);
    length += r.length;
    solved += r.solved() ? 1 : 0;
    ++o.seed;
  }
  state.SetLabel(planner::to_string(o.algorithm));
  state.counters["solved_fraction"] =
      benchmark::Counter(static_cast<double>(solved), benchmark::Counter::kAvgIterations);
  state.counters["mean_length_m"] = benchmark::Counter(length, benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_Plan)
    ->ArgsProduct({{static_cast<int>(PlannerAlgorithm::kRrtStar), static_cast<int>(PlannerAlgorithm::kPrmStar),
                    static_cast<int>(PlannerAlgorithm::kInformedRrtStar)},
                   {2000, 10000}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
