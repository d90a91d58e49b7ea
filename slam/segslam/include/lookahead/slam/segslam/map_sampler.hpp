// SPDX-License-Identifier: MIT
// Local metric map samples (Fairfield et al. 2010, SegSLAM sec. 4.4): submaps of the SegMap placed in
// one frame by growing breadth-first from a start submap. Each visited segment contributes
// one member, drawn at random (SegSLAM eq. (12) combines members of compatible segments freely); a
// segment that is not temporally compatible with those already chosen is skipped; the order
// of expansion within a depth is shuffled ("ties are broken by randomly selecting the
// order"), so different samples close loops differently. Links followed:
//   predecessor p of s:  F_p = F_s (+) T_s(s) (+) T_e(p)^-1
//   successor q of s:    F_q = F_s (+) T_e(s) (+) T_s(q)^-1
//   match parent/child:  the same frame (a match copies its parent's map in its frame).
#pragma once

#include <algorithm>
#include <cstddef>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "lookahead/slam/segslam/seg_map.hpp"

namespace lookahead::slam::segslam {

template <class Pose>
struct PlacedSubmap {
  std::size_t id = kNoSubmap;  ///< kNoSubmap for the start when it is an open submap
  Pose frame;                  ///< the submap frame's origin in the sample frame
  int depth = 0;               ///< link steps from the start
  /// The placed submap (index into the sample) it was reached from, and by which link: 0
  /// its predecessor, 1 its successor, 2 its match parent, 3 its match child (-1: the start).
  /// The chain of links is how its frame was composed (the uncertainty SegSLAM sec. 4.5.2 speaks of).
  std::size_t from = 0;
  int link = -1;
};

/// Grows a sample from `start` (an open submap not yet in `segmap`, or a stored one; its own
/// id or kNoSubmap), in the start's frame, until `max_submaps` are placed or nothing is left.
template <class Map, class Pose>
std::vector<PlacedSubmap<Pose>> sample_local_map(const SegMap<Map, Pose>& segmap, const Submap<Map, Pose>& start,
                                                 std::size_t start_id, std::size_t max_submaps, std::mt19937_64& rng) {
  using Key = std::pair<std::size_t, std::size_t>;
  std::vector<PlacedSubmap<Pose>> placed{{start_id, Pose{}, 0}};
  std::vector<Interval> chosen{start.interval};
  std::set<Key> segments{{start.interval.first_scan, start.interval.last_scan}};
  auto submap_of = [&](std::size_t i) -> const Submap<Map, Pose>& { return i == 0 ? start : segmap.at(placed[i].id); };
  // Places one member of `id`'s segment (a random one unless `exact`) at the frame given by
  // `frame_of(member)`, when its segment is new and compatible.
  auto try_place = [&](std::size_t id, bool exact, int depth, std::size_t from, int link, auto&& frame_of) {
    if (!segmap.contains(id) || placed.size() >= max_submaps) return;
    const Interval& in = segmap.at(id).interval;
    if (segments.count({in.first_scan, in.last_scan})) return;
    for (const Interval& c : chosen)
      if (!in.compatible_with(c)) return;
    std::size_t pick = id;
    if (!exact) {
      const std::vector<std::size_t> members = segmap.segment_of(id);
      pick = members[std::uniform_int_distribution<std::size_t>(0, members.size() - 1)(rng)];
    }
    segments.insert({in.first_scan, in.last_scan});
    chosen.push_back(in);
    placed.push_back({pick, frame_of(segmap.at(pick)), depth, from, link});
  };
  std::vector<std::size_t> level{0};
  for (int depth = 1; !level.empty(); ++depth) {
    std::shuffle(level.begin(), level.end(), rng);
    std::vector<std::size_t> next;
    for (std::size_t i : level) {
      const std::size_t before = placed.size();
      const Submap<Map, Pose>& s = submap_of(i);
      const Pose f = placed[i].frame;
      std::vector<std::pair<std::size_t, int>> links;  // (id, kind): 0 pred, 1 succ, 2 parent, 3 child
      if (s.predecessor != kNoSubmap) links.push_back({s.predecessor, 0});
      if (s.parent != kNoSubmap) links.push_back({s.parent, 2});
      if (placed[i].id != kNoSubmap && segmap.contains(placed[i].id)) {
        for (std::size_t m : segmap.segment_of(placed[i].id)) {
          for (std::size_t q : segmap.successors(m)) links.push_back({q, 1});
        }
        for (std::size_t c : segmap.children(placed[i].id)) links.push_back({c, 3});
      }
      std::shuffle(links.begin(), links.end(), rng);
      for (const auto& [id, kind] : links) {
        if (kind == 0)
          try_place(id, false, depth, i, kind,
                    [&](const auto& p) { return f.compose(s.entry).compose(p.exit.inverse()); });
        if (kind == 1)
          try_place(id, false, depth, i, kind,
                    [&](const auto& q) { return f.compose(s.exit).compose(q.entry.inverse()); });
        if (kind >= 2) try_place(id, true, depth, i, kind, [&](const auto&) { return f; });
      }
      for (std::size_t k = before; k < placed.size(); ++k) next.push_back(k);
    }
    level = std::move(next);
  }
  return placed;
}

}  // namespace lookahead::slam::segslam
