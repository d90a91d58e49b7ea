// SPDX-License-Identifier: MIT
// Offline map sampling and the minimum-entropy map (Fairfield et al. 2010, sec. 5.4):
// many full map samples are grown breadth-first from the particles' submaps (sec. 4.4),
// each is pasted into one grid, and the sample of least entropy
//   H(theta) = sum over observed cells of gamma H(theta[x, y]),  gamma = cell area  (eq. 20-22)
// is the SegMap's best global map.
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/segslam/seg_slam.hpp"
#include "lookahead/slam/segslam/segment_picture.hpp"

namespace lookahead::slam::segslam {

struct MapSample {
  std::size_t particle = 0;                 ///< the particle whose submap the sample grew from
  std::vector<PlacedSubmap<Pose2>> placed;  ///< frames in the first submap's frame when reached
  ProbabilityMap map;
  double entropy = 0.0;                     ///< eq. 22 [nats m^2]
};

/// Eq. 22 with gamma = the cell area: comparable across resolutions [nats m^2].
double scaled_entropy(const ProbabilityMap& map);

/// One full map sample grown from particle `particle`'s open submap.
MapSample sample_full_map(const SegSlam& filter, std::size_t particle, std::mt19937_64& rng);

/// The robot's path as the sample places it: each placed submap's own path in its sample
/// frame, in time order, with an X where a placed submap was a re-entry. What the map of the
/// sample was built from, so a picture of the two agrees (the best particle's eq. 11 chain may
/// place its submaps differently).
SegmentedPath sample_paths(const SegSlam& filter, const MapSample& sample);

struct MinEntropyResult {
  MapSample best;
  std::vector<double> entropies;  ///< of every sample, in drawing order
};

/// `samples` samples from particles drawn by weight; returns the one of least entropy.
/// Samples are drawn in parallel on `threads` threads (0 = all cores), deterministically.
MinEntropyResult min_entropy_search(const SegSlam& filter, int samples, std::uint64_t seed, int threads = 0);

}  // namespace lookahead::slam::segslam
