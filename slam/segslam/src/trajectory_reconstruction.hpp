// SPDX-License-Identifier: MIT
// Reconstructed trajectories (Fairfield et al. 2010, SegSLAM eq. 11-12): a chain of temporally
// sequential submaps, each with its path in its own frame, brought into the frame of the
// first one by composing exit and entry transforms,
//   x_t = concatenate(x[1], T[1]-> T->[2] x[2], ...),   T[i]-> = T_e(i), T->[j] = T_s(j)^-1.
// SegSLAM eq. (12) is the same composition over members of different particles' compatible segments.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "lookahead/slam/segslam/seg_map.hpp"

namespace lookahead::slam::segslam {

/// The frame of each submap of `chain` (oldest first) in the frame of chain[0].
template <class Map, class Pose>
std::vector<Pose> chain_frames(const std::vector<const Submap<Map, Pose>*>& chain) {
  std::vector<Pose> frames;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    frames.push_back(i == 0 ? Pose{} : frames.back().compose(chain[i - 1]->exit).compose(chain[i]->entry.inverse()));
  }
  return frames;
}

/// The submaps a particle went through, oldest first, ending with its open submap `last`.
template <class Map, class Pose>
std::vector<const Submap<Map, Pose>*> temporal_chain(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& last) {
  std::vector<const Submap<Map, Pose>*> chain{&last};
  while (chain.back()->predecessor != kNoSubmap && segmap.contains(chain.back()->predecessor)) {
    chain.push_back(&segmap.at(chain.back()->predecessor));
  }
  std::reverse(chain.begin(), chain.end());
  return chain;
}

/// The poses of the chain's paths, each placed by its frame (frames[i] for chain[i]); at a
/// switch scan the newer submap's pose is kept.
template <class Map, class Pose>
std::vector<std::pair<std::size_t, Pose>> reconstruct_trajectory(const std::vector<const Submap<Map, Pose>*>& chain,
                                                                 const std::vector<Pose>& frames) {
  std::vector<std::pair<std::size_t, Pose>> out;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    for (const auto& [scan, pose] : chain[i]->path) {
      while (!out.empty() && out.back().first >= scan) out.pop_back();
      out.push_back({scan, frames[i].compose(pose)});
    }
  }
  return out;
}

}  // namespace lookahead::slam::segslam

namespace lookahead::slam::segslam {

/// The submap at the top of `s`'s parent links: submaps copied from one another by matches
/// share its frame.
template <class Map, class Pose>
const Submap<Map, Pose>* frame_root(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& s) {
  const Submap<Map, Pose>* r = &s;
  while (r->parent != kNoSubmap && segmap.contains(r->parent)) r = &segmap.at(r->parent);
  return r;
}

/// SegSLAM eq. (11) frames for a particle's chain, except that a submap re-entered by a match takes
/// the frame its parent already has in the chain: the loop closes there (the jump a picture
/// marks with an X), and the rest of the chain follows from the matched frame.
template <class Map, class Pose>
std::vector<Pose> chain_frames_with_matches(const SegMap<Map, Pose>& segmap,
                                            const std::vector<const Submap<Map, Pose>*>& chain) {
  std::vector<Pose> frames =
      chain_frames(std::vector<const Submap<Map, Pose>*>(chain.begin(), chain.begin() + (chain.empty() ? 0 : 1)));
  std::vector<std::pair<const Submap<Map, Pose>*, Pose>> placed_roots;
  if (!chain.empty()) placed_roots.push_back({frame_root(segmap, *chain[0]), frames[0]});
  for (std::size_t i = 1; i < chain.size(); ++i) {
    Pose f = frames.back().compose(chain[i - 1]->exit).compose(chain[i]->entry.inverse());
    const auto* root = frame_root(segmap, *chain[i]);
    bool matched = false;
    for (const auto& [r, rf] : placed_roots) {
      // Members of one segment are interchangeable (SegSLAM eq. (12)): a match into another particle's
      // copy of a segment this chain went through closes the loop the same way.
      if (r->interval == root->interval) f = rf, matched = true;
    }
    if (!matched) placed_roots.push_back({root, f});
    frames.push_back(f);
  }
  return frames;
}

}  // namespace lookahead::slam::segslam
