// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/octree_map_samples.hpp"

#include <algorithm>
#include <limits>

#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "placed_paths.hpp"

namespace lookahead::slam::segslam {

OctreeMapSample sample_full_map(const SegSlam3d& filter, std::size_t particle, std::mt19937_64& rng) {
  const OctreeSegMap& segmap = filter.segmap();
  const OctreeSubmap& start = filter.particles().at(particle).submap;
  OctreeMapSample s;
  s.particle = particle;
  s.placed = sample_local_map(segmap, start, kNoSubmap, std::numeric_limits<std::size_t>::max(), rng);
  auto submap_of = [&](std::size_t i) -> const OctreeSubmap& { return i == 0 ? start : segmap.at(s.placed[i].id); };
  // Re-anchor on the first segment (the odometry frame of the first sweep) when reached.
  for (std::size_t i = 0; i < s.placed.size(); ++i) {
    if (submap_of(i).interval.first_scan != 0) continue;
    const Pose4 to_world = s.placed[i].frame.inverse();
    for (auto& p : s.placed) p.frame = to_world.compose(p.frame);
    break;
  }
  paste_sample(filter, s);
  return s;
}

void paste_sample(const SegSlam3d& filter, OctreeMapSample& s) {
  OctreeCanvas canvas(filter.options().filter.map);
  paste_placed(filter.segmap(), filter.particles().at(s.particle).submap, s.placed, canvas);
  s.entropy = canvas.entropy();
  s.map = canvas.to_octree();
}

OctreeMapSample particle_chain_sample(const SegSlam3d& filter, std::size_t particle) {
  OctreeMapSample s;
  s.particle = particle;
  s.chain = true;
  s.placed = chain_placement(filter.segmap(), filter.particles().at(particle).submap);  // as SegSlam3d::trajectory
  paste_sample(filter, s);
  return s;
}

std::vector<Pose4> sample_trajectory_at_every_sweep(const SegSlam3d& filter, const OctreeMapSample& sample) {
  const auto& sweeps = filter.sweeps();
  return placed_path_at_every_scan(
      filter.segmap(), filter.particles().at(sample.particle).submap, sample.placed, sweeps.size(),
      [&](std::size_t from, std::size_t to) {
        return Pose4::level_of(sweeps[from].odometry).between(Pose4::level_of(sweeps[to].odometry));
      });
}

SegmentedPath sample_paths(const SegSlam3d& filter, const OctreeMapSample& sample) {
  return placed_paths(filter.segmap(), filter.particles().at(sample.particle).submap, sample.placed,
                      [](const Pose4& p) { return p.planar(); });
}

OctreeMinEntropyResult min_entropy_search(const SegSlam3d& filter, int samples, std::uint64_t seed) {
  const std::vector<double> w = particle_weights(filter.particles());
  OctreeMinEntropyResult r;
  // samples 0: the chain alone (offline.particle_chain; validated), else at least one sample.
  const int drawn = filter.options().segslam.offline.particle_chain ? std::max(0, samples) : std::max(1, samples);
  for (int i = 0; i < drawn; ++i) {
    std::mt19937_64 rng(mix_seed(seed, 0xE273D, static_cast<std::uint64_t>(i)));
    std::discrete_distribution<std::size_t> pick(w.begin(), w.end());
    OctreeMapSample s = sample_full_map(filter, pick(rng), rng);
    r.entropies.push_back(s.entropy);
    if (i == 0 || s.entropy < r.best.entropy) r.best = std::move(s);
  }
  if (filter.options().segslam.offline.particle_chain) {
    OctreeMapSample chain = particle_chain_sample(filter, filter.best_particle());
    r.chain_entropy = chain.entropy;
    if (drawn == 0 || chain.entropy < r.best.entropy) r.best = std::move(chain);
  }
  return r;
}

}  // namespace lookahead::slam::segslam
