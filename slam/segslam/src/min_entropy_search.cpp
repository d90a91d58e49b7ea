// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/min_entropy_search.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

#include "lookahead/slam/eval/map_entropy.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "placed_paths.hpp"

namespace lookahead::slam::segslam {

double scaled_entropy(const ProbabilityMap& map) { return map_entropy(map).total * map.resolution * map.resolution; }

MapSample sample_full_map(const SegSlam& filter, std::size_t particle, std::mt19937_64& rng) {
  const GridSegMap& segmap = filter.segmap();
  const GridSubmap& start = filter.particles().at(particle).submap;
  MapSample s;
  s.particle = particle;
  s.placed = sample_local_map(segmap, start, kNoSubmap, std::numeric_limits<std::size_t>::max(), rng);
  auto submap_of = [&](std::size_t i) -> const GridSubmap& { return i == 0 ? start : segmap.at(s.placed[i].id); };
  // Re-anchor on the first segment (the odometry frame of the first scan) when reached.
  for (std::size_t i = 0; i < s.placed.size(); ++i) {
    if (submap_of(i).interval.first_scan != 0) continue;
    const Pose2 to_world = s.placed[i].frame.inverse();
    for (auto& p : s.placed) p.frame = to_world.compose(p.frame);
    break;
  }
  paste_sample(filter, s);
  return s;
}

void paste_sample(const SegSlam& filter, MapSample& s) {
  const GridOptions& grid = filter.rbpf_options().grid;
  MapCanvas canvas(grid.resolution, grid.log_odds_min, grid.log_odds_max);
  paste_placed(filter.segmap(), filter.particles().at(s.particle).submap, s.placed, canvas);
  s.map = canvas.to_probability_map();
  s.entropy = scaled_entropy(s.map);
}

MapSample particle_chain_sample(const SegSlam& filter, std::size_t particle) {
  MapSample s;
  s.particle = particle;
  s.chain = true;
  s.placed = chain_placement(filter.segmap(), filter.particles().at(particle).submap);  // as SegSlam::trajectory
  paste_sample(filter, s);
  return s;
}

SegmentedPath sample_paths(const SegSlam& filter, const MapSample& sample) {
  return placed_paths(filter.segmap(), filter.particles().at(sample.particle).submap, sample.placed,
                      [](const Pose2& p) { return p; });
}

std::vector<Pose2> sample_trajectory_at_every_scan(const SegSlam& filter, const MapSample& sample) {
  const std::vector<LaserScan>& scans = filter.scans();
  return placed_path_at_every_scan(
      filter.segmap(), filter.particles().at(sample.particle).submap, sample.placed, scans.size(),
      [&](std::size_t from, std::size_t to) { return scans[from].odometry.between(scans[to].odometry); });
}

MinEntropyResult min_entropy_search(const SegSlam& filter, int samples, std::uint64_t seed, int threads) {
  const std::vector<double> w = particle_weights(filter.particles());
  std::vector<MapSample> drawn(static_cast<std::size_t>(samples));
  const int t = threads > 0 ? threads : omp_get_num_procs();
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(t)
  for (int i = 0; i < samples; ++i) {
    errors.run([&] {
      std::mt19937_64 rng(mix_seed(seed, 0xE27, static_cast<std::uint64_t>(i)));
      std::discrete_distribution<std::size_t> pick(w.begin(), w.end());
      drawn[static_cast<std::size_t>(i)] = sample_full_map(filter, pick(rng), rng);
    });
  }
  errors.rethrow();
  MinEntropyResult r;
  if (drawn.empty()) {  // map_samples 0 (validated: only with offline.particle_chain)
    r.best = particle_chain_sample(filter, filter.best_particle());
    r.chain_entropy = r.best.entropy;
    return r;
  }
  std::size_t best = 0;
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    r.entropies.push_back(drawn[i].entropy);
    if (drawn[i].entropy < drawn[best].entropy) best = i;
  }
  r.best = std::move(drawn[best]);
  if (filter.options().offline.particle_chain) {
    MapSample chain = particle_chain_sample(filter, filter.best_particle());
    r.chain_entropy = chain.entropy;
    if (chain.entropy < r.best.entropy) r.best = std::move(chain);
  }
  return r;
}

}  // namespace lookahead::slam::segslam
