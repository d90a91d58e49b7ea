// SPDX-License-Identifier: MIT
// The SegMap Theta = {theta_0, theta_1, ...} (Fairfield et al. 2010, SegSLAM sec. 4.1-4.4): every
// closed submap, the links between them (temporal predecessor, match parent), and the
// segments, the groups of particle submaps that share one interval. Submaps of segments
// that can no longer be part of any reconstructed trajectory are pruned (SegSLAM sec. 4.4,
// "non-viable segments").
#pragma once

#include <algorithm>
#include <cstddef>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "lookahead/slam/segslam/submap.hpp"

namespace lookahead::slam::segslam {

template <class Map, class Pose>
class SegMap {
 public:
  using SubmapT = Submap<Map, Pose>;

  /// Stores a closed submap; returns its id (ids are never reused).
  std::size_t add(SubmapT submap) {
    const std::size_t id = submaps_.size();
    if (submap.predecessor != kNoSubmap) successors_[submap.predecessor].push_back(id);
    if (submap.parent != kNoSubmap) children_[submap.parent].push_back(id);
    segments_[key(submap.interval)].push_back(id);
    submaps_.push_back(std::make_shared<const SubmapT>(std::move(submap)));
    return id;
  }

  [[nodiscard]] bool contains(std::size_t id) const { return id < submaps_.size() && submaps_[id]; }
  [[nodiscard]] const SubmapT& at(std::size_t id) const { return *submaps_.at(id); }
  [[nodiscard]] std::size_t id_bound() const { return submaps_.size(); }
  [[nodiscard]] std::size_t live_count() const {
    return static_cast<std::size_t>(
        std::count_if(submaps_.begin(), submaps_.end(), [](const auto& s) { return s != nullptr; }));
  }
  [[nodiscard]] std::size_t segment_count() const { return segments_.size(); }
  /// Live submaps that hold a map of their own (not merged into a parent).
  [[nodiscard]] std::size_t map_count() const {
    return static_cast<std::size_t>(
        std::count_if(submaps_.begin(), submaps_.end(), [](const auto& s) { return s && !s->merged; }));
  }

  /// Merges the stored match child `id` into its parent (SegSLAM sec. 6: "submaps can be quickly
  /// merged by adding the evidence grids when their relative positions become certain"; a
  /// match child shares its parent's frame, so the match gives the relative position):
  /// `add_evidence(parent_map, child_map)` adds what the child observed to the parent's map,
  /// then the child drops its map and keeps only its interval, poses and links. Returns
  /// false (and changes nothing) when `id` is merged already or has no live parent.
  template <class AddEvidence>
  bool merge_into_parent(std::size_t id, AddEvidence&& add_evidence) {
    if (!contains(id) || at(id).merged || !contains(at(id).parent)) return false;
    const std::size_t p = at(id).parent;
    auto parent = std::make_shared<SubmapT>(at(p));
    add_evidence(parent->map, at(id).map);
    ++parent->merged_visits;
    auto child = std::make_shared<SubmapT>(at(id));
    child->map = Map{};
    child->merged = true;
    submaps_[p] = std::move(parent);
    submaps_[id] = std::move(child);
    return true;
  }

  /// The submap holding `id`'s evidence: `id` itself, or for a merged submap the parent its
  /// evidence went into (same frame), followed while that is merged too. A match to a
  /// merged submap is a match to this one.
  [[nodiscard]] std::size_t map_holder(std::size_t id) const {
    while (contains(id) && at(id).merged && contains(at(id).parent)) id = at(id).parent;
    return id;
  }

  /// The live members of the segment holding `id` (the submaps with its interval).
  [[nodiscard]] std::vector<std::size_t> segment_of(std::size_t id) const {
    const auto it = segments_.find(key(at(id).interval));
    std::vector<std::size_t> out;
    if (it != segments_.end()) {
      for (std::size_t m : it->second)
        if (contains(m)) out.push_back(m);
    }
    return out;
  }
  /// The first (lowest-id) live copy of `id`'s segment that holds a map and has the same
  /// parent chain (the intervals of its parent, its parent's parent, ...): the same frame (a
  /// fresh submap's starts at the robot at its first scan, a match child takes its parent's)
  /// and the same stretch of the world, up to the particles' noise (a match child's map holds
  /// its ancestors'). `id` itself when no lower copy qualifies.
  [[nodiscard]] std::size_t first_copy(std::size_t id) const {
    const std::vector<Key> own = lineage(id);
    for (const std::size_t m : segment_of(id)) {  // ascending ids
      if (m >= id) break;
      if (!at(m).merged && lineage(m) == own) return m;
    }
    return id;
  }
  [[nodiscard]] std::vector<std::size_t> successors(std::size_t id) const { return live(successors_, id); }
  [[nodiscard]] std::vector<std::size_t> children(std::size_t id) const { return live(children_, id); }

  /// Keeps the segments reachable from the `roots` (the links of the particles' open
  /// submaps) through predecessor and parent links, with every member of a reachable
  /// segment (SegSLAM eq. (12) may combine any of them); drops the rest. Returns how many were dropped.
  std::size_t prune(const std::vector<std::size_t>& roots) {
    std::set<Key> viable;
    std::vector<std::size_t> stack;
    for (std::size_t r : roots)
      if (contains(r)) stack.push_back(r);
    while (!stack.empty()) {
      const std::size_t id = stack.back();
      stack.pop_back();
      if (!viable.insert(key(at(id).interval)).second) continue;
      for (std::size_t m : segment_of(id)) {
        for (std::size_t next : {at(m).predecessor, at(m).parent}) {
          if (contains(next) && !viable.count(key(at(next).interval))) stack.push_back(next);
        }
      }
    }
    std::size_t dropped = 0;
    for (auto& s : submaps_) {
      if (s && !viable.count(key(s->interval))) {
        s.reset();
        ++dropped;
      }
    }
    return dropped;
  }

 private:
  using Key = std::pair<std::size_t, std::size_t>;
  static Key key(const Interval& i) { return {i.first_scan, i.last_scan}; }
  std::vector<Key> lineage(std::size_t id) const {
    std::vector<Key> out;
    for (; id != kNoSubmap && contains(id); id = at(id).parent) out.push_back(key(at(id).interval));
    return out;
  }
  std::vector<std::size_t> live(const std::map<std::size_t, std::vector<std::size_t>>& links, std::size_t id) const {
    std::vector<std::size_t> out;
    const auto it = links.find(id);
    if (it != links.end()) {
      for (std::size_t m : it->second)
        if (contains(m)) out.push_back(m);
    }
    return out;
  }

  std::vector<std::shared_ptr<const SubmapT>> submaps_;  // by id; null once pruned
  std::map<std::size_t, std::vector<std::size_t>> successors_, children_;
  std::map<Key, std::vector<std::size_t>> segments_;
};

}  // namespace lookahead::slam::segslam
