// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/octree_map_samples.hpp"

#include <limits>

#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/rbpf/resampler.hpp"

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
  OctreeCanvas canvas(filter.options().filter.map);
  for (std::size_t i = 0; i < s.placed.size(); ++i) {
    const OctreeSubmap& m = submap_of(i);
    const EvidenceOctree* parent = nullptr;
    for (std::size_t j = 0; j < i && m.parent != kNoSubmap; ++j) {
      if (s.placed[j].id == m.parent) parent = &segmap.at(m.parent).map;
    }
    canvas.paste(m.map, s.placed[i].frame, parent);
  }
  s.entropy = canvas.entropy();
  s.map = canvas.to_octree();
  return s;
}

OctreeMinEntropyResult min_entropy_search(const SegSlam3d& filter, int samples, std::uint64_t seed) {
  std::vector<double> logw;
  for (const SegParticle3& p : filter.particles()) logw.push_back(p.log_weight);
  const std::vector<double> w = normalized_weights(logw);
  OctreeMinEntropyResult r;
  for (int i = 0; i < std::max(1, samples); ++i) {
    std::mt19937_64 rng(mix_seed(seed, 0xE273D, static_cast<std::uint64_t>(i)));
    std::discrete_distribution<std::size_t> pick(w.begin(), w.end());
    OctreeMapSample s = sample_full_map(filter, pick(rng), rng);
    r.entropies.push_back(s.entropy);
    if (i == 0 || s.entropy < r.best.entropy) r.best = std::move(s);
  }
  return r;
}

}  // namespace lookahead::slam::segslam
