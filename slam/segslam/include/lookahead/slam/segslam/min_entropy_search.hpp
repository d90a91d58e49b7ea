// SPDX-License-Identifier: MIT
// Offline map sampling and the minimum-entropy map (Fairfield et al. 2010, SegSLAM sec. 5.4):
// many full map samples are grown breadth-first from the particles' submaps (SegSLAM sec. 4.4),
// each is pasted into one grid, and the sample of least entropy
//   H(theta) = sum over observed cells of gamma H(theta[x, y]),  gamma = cell area  (SegSLAM eq. (20)-(22))
// is the SegMap's best global map.
//
// Deviation (offline.particle_chain; on in 2D, off in 3D's defaults): the best particle's own
// chain of submaps, placed as its SegSLAM eq. (11) trajectory places them (a re-entry closes the loop in
// the matched frame), is a candidate too. A breadth-first sample composes each frame along one
// path through the SegMap and skips the link that closes a loop, so the loop's whole drift
// shows at that junction, and it mixes members of other particles' lineages: long corridors
// come out doubled. The particle's chain is consistent with the trajectory a run writes.
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
  double entropy = 0.0;  ///< SegSLAM eq. (22) [nats m^2]
  bool chain = false;    ///< the particle's own chain, not grown breadth-first
};

/// SegSLAM eq. (22) with gamma = the cell area: comparable across resolutions [nats m^2].
double scaled_entropy(const ProbabilityMap& map);

/// One full map sample grown from particle `particle`'s open submap.
MapSample sample_full_map(const SegSlam& filter, std::size_t particle, std::mt19937_64& rng);

/// The map of particle `particle`'s own chain of submaps, each placed where its SegSLAM eq. (11)
/// trajectory places it (SegSlam::trajectory): the sample whose path is the particle's.
MapSample particle_chain_sample(const SegSlam& filter, std::size_t particle);

/// Pastes the submaps of `sample.placed` at their frames into `sample.map` and scores it (SegSLAM eq. (22)).
void paste_sample(const SegSlam& filter, MapSample& sample);

/// The robot's path as the sample places it: each placed submap's own path in its sample
/// frame, in time order, with an X where a placed submap was a re-entry. What the map of the
/// sample was built from, so a picture of the two agrees (the best particle's SegSLAM eq. (11) chain may
/// place its submaps differently).
SegmentedPath sample_paths(const SegSlam& filter, const MapSample& sample);

/// The robot's pose at every scan as the sample places it: the placed submaps' path poses
/// (at a switch scan the newer submap's), scans between them by dead reckoning.
std::vector<Pose2> sample_trajectory_at_every_scan(const SegSlam& filter, const MapSample& sample);

struct MinEntropyResult {
  MapSample best;
  std::vector<double> entropies;  ///< of every sample grown breadth-first, in drawing order
  double chain_entropy = 0.0;     ///< of the best particle's chain (offline.particle_chain; else 0)
};

/// `samples` samples from particles drawn by weight, and the best particle's chain
/// (offline.particle_chain); returns the one of least entropy.
/// Samples are drawn in parallel on `threads` threads (0 = all cores), deterministically.
MinEntropyResult min_entropy_search(const SegSlam& filter, int samples, std::uint64_t seed, int threads = 0);

}  // namespace lookahead::slam::segslam
