// SPDX-License-Identifier: MIT
// Offline map samples of a 3D SegMap and the minimum-entropy map (Fairfield et al. 2010,
// SegSLAM sec. 5.4, SegSLAM eq. (20)-(22)), as min_entropy_search.hpp does in 2D: full samples grown breadth-
// first (SegSLAM sec. 4.4, the generic sample_local_map) from particles drawn by weight, each pasted
// into one octree canvas; the sample of least entropy is the SegMap's best global map. As in
// 2D (a deviation, min_entropy_search.hpp), the best particle's own chain of submaps is a
// candidate too (offline.particle_chain).
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"

namespace lookahead::slam::segslam {

struct OctreeMapSample {
  std::size_t particle = 0;
  std::vector<PlacedSubmap<Pose4>> placed;  ///< frames in the first submap's frame when reached
  double entropy = 0.0;                     ///< SegSLAM eq. (22) [nats m^3]
  EvidenceOctree map;
  bool chain = false;  ///< the particle's own chain, not grown breadth-first
};

/// One full map sample grown from particle `particle`'s open submap.
OctreeMapSample sample_full_map(const SegSlam3d& filter, std::size_t particle, std::mt19937_64& rng);

/// The map of particle `particle`'s own chain of submaps, each placed where its SegSLAM eq. (11)
/// trajectory places it (SegSlam3d::trajectory).
OctreeMapSample particle_chain_sample(const SegSlam3d& filter, std::size_t particle);

/// Pastes the submaps of `sample.placed` at their frames into `sample.map` and scores it (SegSLAM eq. (22)).
void paste_sample(const SegSlam3d& filter, OctreeMapSample& sample);

/// The robot's pose at every sweep as the sample places it (the placed submaps' path poses,
/// sweeps between them by levelled dead reckoning).
std::vector<Pose4> sample_trajectory_at_every_sweep(const SegSlam3d& filter, const OctreeMapSample& sample);

/// The robot's path as the sample places it, from above: each placed submap's own path in its
/// sample frame, in time order, with an X where a placed submap was a re-entry (as 2D's
/// sample_paths): what the sample's map was built from, so a picture of the two agrees.
SegmentedPath sample_paths(const SegSlam3d& filter, const OctreeMapSample& sample);

struct OctreeMinEntropyResult {
  OctreeMapSample best;
  std::vector<double> entropies;  ///< of every sample grown breadth-first, in drawing order
  double chain_entropy = 0.0;     ///< of the best particle's chain (offline.particle_chain; else 0)
};

/// `samples` samples from particles drawn by weight, one after another, and the best
/// particle's chain (offline.particle_chain; then `samples` may be 0); the least entropy wins.
OctreeMinEntropyResult min_entropy_search(const SegSlam3d& filter, int samples, std::uint64_t seed);

}  // namespace lookahead::slam::segslam
