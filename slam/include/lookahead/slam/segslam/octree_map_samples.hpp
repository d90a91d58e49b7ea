// SPDX-License-Identifier: MIT
// Offline map samples of a 3D SegMap and the minimum-entropy map (Fairfield et al. 2010,
// sec. 5.4, eq. 20-22), as min_entropy_search.hpp does in 2D: full samples grown breadth-
// first (sec. 4.4, the generic sample_local_map) from particles drawn by weight, each pasted
// into one octree canvas; the sample of least entropy is the SegMap's best global map.
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
  double entropy = 0.0;                     ///< eq. 22 [nats m^3]
  EvidenceOctree map;
};

/// One full map sample grown from particle `particle`'s open submap.
OctreeMapSample sample_full_map(const SegSlam3d& filter, std::size_t particle, std::mt19937_64& rng);

struct OctreeMinEntropyResult {
  OctreeMapSample best;
  std::vector<double> entropies;  ///< of every sample, in drawing order
};

/// `samples` samples (>= 1) from particles drawn by weight, one after another; the least
/// entropy wins.
OctreeMinEntropyResult min_entropy_search(const SegSlam3d& filter, int samples, std::uint64_t seed);

}  // namespace lookahead::slam::segslam
