// SPDX-License-Identifier: MIT
// SegSLAM 3D's capped searches (SegSLAM sec. 4.5.2; the reach of candidate_reach.hpp), one per
// searched submap and update: the particles ask for them while they predict
// (SegSlam3d::ask_matches), and the requests on one submap (a segment's first copy, or the
// candidate itself with matching.share_by_segment off) are searched together, each guess's
// rounded region answered from one grid (match_regions), before the particles draw.
//
// Why: the particles match at the same updates (they descend from few resampled parents)
// and ask for many capped searches per such update, from map-sample guesses a metre or two
// apart on the copies of one or two segments: each search's grid covers most of the others',
// and ICP from their best poses mostly converges to one pose.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "localization_match3.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "seg_slam3d_transition.hpp"

namespace lookahead::slam::segslam {

void SegSlam3d::run_capped_stage(std::vector<Transition>& transitions, const SweepWindow& w) {
  struct Member {
    std::size_t particle, candidate, search, region;
  };
  std::vector<CappedSearch> searches;
  std::vector<Member> members;
  // By (submap searched, height cell): the coarse search is level, at its centre's height.
  std::map<std::pair<std::size_t, long>, std::vector<std::size_t>> open;  // -> indices into searches
  // A request joins a search whose square, with its region, stays within this (a guess far
  // from the others would make the square, and its cost, grow).
  const double max_square =
      2 * std::max(options_.segslam.matching.max_search_radius, options_.segslam.matching.search_radius);
  for (std::size_t u = 0; u < transitions.size(); ++u) {
    for (std::size_t k = 0; k < transitions[u].candidates.size(); ++k) {
      const Candidate& c = transitions[u].candidates[k];
      if (c.wide_only) continue;
      const std::size_t searched = options_.segslam.matching.share_by_segment ? segmap_.first_copy(c.id) : c.id;
      const MatchingOptions o = candidate_options(searched);
      const LevelSubgrid region = capped_region(c.guess, o);
      std::vector<std::size_t>& groups = open[{searched, std::lround(region.centre.z / 0.5)}];
      std::size_t joined = searches.size();
      for (const std::size_t g : groups) {
        if (covering_subgrid(searches[g].regions.front(), {region}).radius <= max_square) {
          joined = g;
          break;
        }
      }
      if (joined == searches.size()) {
        groups.push_back(joined);
        searches.push_back({searched, o, {}, {}});
      }
      std::vector<LevelSubgrid>& regions = searches[joined].regions;
      const auto same = [&](const LevelSubgrid& r) { return key_of(searched, r) == key_of(searched, region); };
      const auto at = std::find_if(regions.begin(), regions.end(), same);
      members.push_back({u, k, joined, static_cast<std::size_t>(at - regions.begin())});
      if (at == regions.end()) regions.push_back(region);
    }
  }
  if (searches.empty()) return;
  // As tasks: a search hands its ICP refinements out as tasks too (match_regions).
  ParallelErrors errors;
#pragma omp parallel num_threads(thread_count())
#pragma omp single
  for (CappedSearch& search : searches) {
#pragma omp task default(shared)
    errors.run([&] { run_capped_search(search, w); });
  }
  errors.rethrow();
  for (const Member& m : members) {
    transitions[m.particle].screens[m.candidate] = searches[m.search].results[m.region];
  }
  stats_.match_requests += members.size();
}

void SegSlam3d::run_capped_search(CappedSearch& s, const SweepWindow& w) {
  const auto start = std::chrono::steady_clock::now();
  if (s.options.use_localization_filter) {
    // SegSLAM eq. (19): a localisation filter per region (nothing to share between them).
    for (const LevelSubgrid& region : s.regions) s.results.push_back(capped_search(s.searched, region, s.options, w));
  } else {
    s.results = match_regions(*target_of(s.searched), window_with_structure(w), s.regions, s.options,
                              options_.extras.structure);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::lock_guard<std::mutex> lock(cache_mutex_);
  stats_.match_attempts += s.regions.size();
  ++stats_.capped_searches;
  stats_.matching_seconds += seconds;
  // The screens stay in the update's cache: a copy fitted again reads it if it is the first.
  for (std::size_t r = 0; r < s.regions.size(); ++r)
    match_cache_.emplace(key_of(s.searched, s.regions[r]), s.results[r]);
}

}  // namespace lookahead::slam::segslam
