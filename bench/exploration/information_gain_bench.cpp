// SPDX-License-Identifier: MIT
// Information gain of one frontier goal, the disc count against line of sight, on a map that
// is half explored: the hospital section of Stage's floor plan known within 10 m of its
// centre (free and wall cells from the plan), unknown beyond. Utility selection prices every
// reachable frontier this way, so this bounds how often it can choose.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "lookahead/exploration/information_gain.hpp"
#include "lookahead/exploration/world_loader.hpp"

namespace {

using lookahead::exploration::World;
using lookahead::slam::OccupancyGrid;

const std::string kPlans = std::string(LOOKAHEAD_SHARED_DIR) + "/data/floorplans/";

struct HalfExplored {
  OccupancyGrid map;
  std::vector<std::pair<double, double>> goals;  // free points of the known part
};

const HalfExplored& hospital() {
  static const HalfExplored h = [] {
    const World w = lookahead::exploration::load_stage_world(kPlans + "stage/worlds/everything.world");
    HalfExplored out;
    const double cx = w.origin().x() + w.width_m() / 2, cy = w.origin().y() + w.height_m() / 2;
    const double res = out.map.resolution();
    for (double y = cy - 10; y < cy + 10; y += res)
      for (double x = cx - 10; x < cx + 10; x += res) {
        if ((x - cx) * (x - cx) + (y - cy) * (y - cy) > 100) continue;
        const auto c = out.map.cell_at(x, y);
        const bool wall = w.is_occupied(x, y);
        for (int k = 0; k < (wall ? 10 : 3); ++k)
          out.map.add_log_odds(c, wall ? out.map.fixed_hit() : out.map.fixed_miss());
        if (!wall && out.goals.size() < 4096 && (c.x * 7 + c.y * 13) % 97 == 0) out.goals.emplace_back(x, y);
      }
    std::shuffle(out.goals.begin(), out.goals.end(), std::mt19937_64(1));
    return out;
  }();
  return h;
}

template <typename Gain>
void run(benchmark::State& state, Gain gain) {
  const HalfExplored& h = hospital();
  const double range = static_cast<double>(state.range(0));
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    const auto& [x, y] = h.goals[i++ % h.goals.size()];
    benchmark::DoNotOptimize(sum += gain(h.map, x, y, range));
  }
  state.counters["goals/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["mean_gain_m2"] = sum / static_cast<double>(state.iterations());
}

void BM_GainDisc(benchmark::State& state) {
  run(state, [](const auto& map, double x, double y, double r) {
    return lookahead::exploration::information_gain(map, x, y, r);
  });
}
void BM_GainLineOfSight(benchmark::State& state) {
  run(state, [](const auto& map, double x, double y, double r) {
    return lookahead::exploration::visible_information_gain(map, x, y, r);
  });
}
BENCHMARK(BM_GainDisc)->Arg(8)->Arg(12);
BENCHMARK(BM_GainLineOfSight)->Arg(8)->Arg(12);

}  // namespace

BENCHMARK_MAIN();
