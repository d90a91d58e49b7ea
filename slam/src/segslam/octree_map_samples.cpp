// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/octree_map_samples.hpp"

#include <algorithm>
#include <limits>

#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/rbpf/resampler.hpp"
#include "lookahead/slam/segslam/trajectory_reconstruction.hpp"

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
  const OctreeSegMap& segmap = filter.segmap();
  const OctreeSubmap& start = filter.particles().at(s.particle).submap;
  auto submap_of = [&](std::size_t i) -> const OctreeSubmap& { return i == 0 ? start : segmap.at(s.placed[i].id); };
  OctreeCanvas canvas(filter.options().filter.map);
  for (std::size_t i = 0; i < s.placed.size(); ++i) {
    const OctreeSubmap& m = submap_of(i);
    const EvidenceOctree* parent = nullptr;
    for (std::size_t j = 0; j < s.placed.size() && m.parent != kNoSubmap; ++j) {
      if (j != i && s.placed[j].id == m.parent) parent = &segmap.at(m.parent).map;
    }
    canvas.paste(m.map, s.placed[i].frame, parent);
  }
  s.entropy = canvas.entropy();
  s.map = canvas.to_octree();
}

OctreeMapSample particle_chain_sample(const SegSlam3d& filter, std::size_t particle) {
  const OctreeSegMap& segmap = filter.segmap();
  const OctreeSubmap& open = filter.particles().at(particle).submap;
  std::vector<std::size_t> ids{kNoSubmap};  // the open submap, then its predecessors
  for (std::size_t id = open.predecessor; id != kNoSubmap && segmap.contains(id); id = segmap.at(id).predecessor) {
    ids.push_back(id);
  }
  std::reverse(ids.begin(), ids.end());
  std::vector<const OctreeSubmap*> chain;
  for (std::size_t id : ids) chain.push_back(id == kNoSubmap ? &open : &segmap.at(id));
  const std::vector<Pose4> frames = chain_frames_with_matches(segmap, chain);  // as SegSlam3d::trajectory
  OctreeMapSample s;
  s.particle = particle;
  s.chain = true;
  s.placed.push_back({kNoSubmap, frames.back(), 0});
  for (std::size_t k = ids.size() - 1; k-- > 0;) {
    s.placed.push_back({ids[k], frames[k], static_cast<int>(s.placed.size()), s.placed.size() - 1, 0});
  }
  paste_sample(filter, s);
  return s;
}

std::vector<Pose4> sample_trajectory_at_every_sweep(const SegSlam3d& filter, const OctreeMapSample& sample) {
  const auto& sweeps = filter.sweeps();
  struct At {
    std::size_t sweep;
    std::size_t submap_start;  // first sweep of the submap the pose is in
    Pose4 pose;                // in the sample frame
  };
  std::vector<At> at;
  for (std::size_t i = 0; i < sample.placed.size(); ++i) {
    const OctreeSubmap& s = i == 0 ? filter.particles().at(sample.particle).submap : filter.segmap().at(sample.placed[i].id);
    for (const auto& [sweep, pose] : s.path) at.push_back({sweep, s.interval.first_scan, sample.placed[i].frame.compose(pose)});
  }
  if (at.empty()) return {};
  // By sweep; at a switch sweep the newer submap's pose comes last, so it is the one used.
  std::sort(at.begin(), at.end(), [](const At& a, const At& b) {
    return a.sweep != b.sweep ? a.sweep < b.sweep : a.submap_start < b.submap_start;
  });
  std::vector<Pose4> out;
  std::size_t k = 0;
  for (std::size_t sweep = 0; sweep < sweeps.size(); ++sweep) {
    while (k + 1 < at.size() && at[k + 1].sweep <= sweep) ++k;
    const Pose4 from = Pose4::level_of(sweeps[at[k].sweep].odometry), to = Pose4::level_of(sweeps[sweep].odometry);
    out.push_back(at[k].pose.compose(from.between(to)));
  }
  return out;
}

SegmentedPath sample_paths(const SegSlam3d& filter, const OctreeMapSample& sample) {
  std::vector<std::pair<const OctreeSubmap*, Pose4>> placed;
  for (std::size_t i = 0; i < sample.placed.size(); ++i) {
    placed.push_back({i == 0 ? &filter.particles().at(sample.particle).submap : &filter.segmap().at(sample.placed[i].id),
                      sample.placed[i].frame});
  }
  std::sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) {
    return a.first->interval.first_scan < b.first->interval.first_scan;
  });
  SegmentedPath out;
  out.label = "paths of the map's submaps, one colour each";
  for (const auto& [submap, frame] : placed) {
    std::vector<Pose2> piece;
    for (const auto& [sweep, pose] : submap->path) piece.push_back(frame.compose(pose).planar());
    out.pieces.push_back(std::move(piece));
    if (submap->parent != kNoSubmap) {
      const Pose4 at = frame.compose(submap->entry);
      out.matches.emplace_back(at.x, at.y);
    }
  }
  return out;
}

OctreeMinEntropyResult min_entropy_search(const SegSlam3d& filter, int samples, std::uint64_t seed) {
  std::vector<double> logw;
  for (const SegParticle3& p : filter.particles()) logw.push_back(p.log_weight);
  const std::vector<double> w = normalized_weights(logw);
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
