// SPDX-License-Identifier: MIT
// A placed set of submaps (a map sample, or a particle's own chain), generic over the map and
// pose types as map_sampler.hpp is: the chain placed as its SegSLAM eq. (11) trajectory places it, its
// submaps pasted into one canvas, and the robot's path as the placement puts it (the pieces a
// picture draws, one pose per scan).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/segslam/segment_picture.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {

/// A particle's own chain of submaps, from its open submap `open` (placed first, id
/// kNoSubmap, as a breadth-first sample starts) back to the oldest, each at the frame its
/// SegSLAM eq. (11) trajectory gives it (chain_frames_with_matches: a re-entry closes the loop in the
/// matched frame), in the frame of the oldest submap.
template <class Map, class Pose>
std::vector<PlacedSubmap<Pose>> chain_placement(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& open) {
  std::vector<std::size_t> ids{kNoSubmap};  // the open submap, then its predecessors
  for (std::size_t id = open.predecessor; id != kNoSubmap && segmap.contains(id); id = segmap.at(id).predecessor) {
    ids.push_back(id);
  }
  std::reverse(ids.begin(), ids.end());
  std::vector<const Submap<Map, Pose>*> chain;
  for (std::size_t id : ids) chain.push_back(id == kNoSubmap ? &open : &segmap.at(id));
  const std::vector<Pose> frames = chain_frames_with_matches(segmap, chain);
  std::vector<PlacedSubmap<Pose>> placed{{kNoSubmap, frames.back(), 0}};
  for (std::size_t k = ids.size() - 1; k-- > 0;) {  // each older one reached from the next
    placed.push_back({ids[k], frames[k], static_cast<int>(placed.size()), placed.size() - 1, 0});
  }
  return placed;
}

/// The placed submaps (the first is `open`, the others by id), oldest first.
template <class Map, class Pose>
std::vector<std::pair<const Submap<Map, Pose>*, Pose>> placed_in_time_order(
    const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& open, const std::vector<PlacedSubmap<Pose>>& placed) {
  std::vector<std::pair<const Submap<Map, Pose>*, Pose>> out;
  for (std::size_t i = 0; i < placed.size(); ++i)
    out.push_back({i == 0 ? &open : &segmap.at(placed[i].id), placed[i].frame});
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    return a.first->interval.first_scan < b.first->interval.first_scan;
  });
  return out;
}

/// Pastes each placed submap (the first is `open`, the others by id) into `canvas` at its frame
/// (`canvas.paste(map, frame, parent_map_or_null)`); a match child whose parent is placed too
/// adds only what it changed, so copied evidence is not counted twice.
template <class Map, class Pose, class Canvas>
void paste_placed(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& open,
                  const std::vector<PlacedSubmap<Pose>>& placed, Canvas& canvas) {
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Submap<Map, Pose>& m = i == 0 ? open : segmap.at(placed[i].id);
    const Map* parent = nullptr;
    for (std::size_t j = 0; j < placed.size() && m.parent != kNoSubmap; ++j) {
      if (j != i && placed[j].id == m.parent) parent = &segmap.at(m.parent).map;
    }
    canvas.paste(m.map, placed[i].frame, parent);
  }
}

/// The path as the placement puts it, for a picture: each submap's own path in its frame, in
/// time order, with an X where a placed submap was a re-entry. `planar(pose)` gives the Pose2.
template <class Map, class Pose, class Planar>
SegmentedPath placed_paths(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& open,
                           const std::vector<PlacedSubmap<Pose>>& placed, Planar&& planar) {
  SegmentedPath out;
  out.label = "paths of the map's submaps, one colour each";
  for (const auto& [submap, frame] : placed_in_time_order(segmap, open, placed)) {
    std::vector<Pose2> piece;
    for (const auto& [scan, pose] : submap->path) piece.push_back(planar(frame.compose(pose)));
    out.pieces.push_back(std::move(piece));
    if (submap->parent != kNoSubmap) {
      const Pose2 at = planar(frame.compose(submap->entry));
      out.matches.emplace_back(at.x, at.y);
    }
  }
  return out;
}

/// One pose per scan 0..scans-1 as the placement puts the path: the placed submaps' path poses
/// (at a switch scan the newer submap's), scans between them carried by `motion(from, to)`,
/// the relative odometry motion from scan `from` to scan `to`.
template <class Map, class Pose, class Motion>
std::vector<Pose> placed_path_at_every_scan(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& open,
                                            const std::vector<PlacedSubmap<Pose>>& placed, std::size_t scans,
                                            Motion&& motion) {
  std::vector<std::pair<std::size_t, Pose>> at;  // (scan, pose), in time order of the submaps
  for (const auto& [submap, frame] : placed_in_time_order(segmap, open, placed)) {
    for (const auto& [scan, pose] : submap->path) at.push_back({scan, frame.compose(pose)});
  }
  // By scan; at a switch scan the newer submap's pose stays last, so it is the one used.
  std::stable_sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return poses_at_every_scan(at, scans, std::forward<Motion>(motion));
}

}  // namespace lookahead::slam::segslam
