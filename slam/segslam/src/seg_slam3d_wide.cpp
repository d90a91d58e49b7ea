// SPDX-License-Identifier: MIT
// SegSLAM 3D's wide re-entry searches (wide_reentry.hpp), one per segment and update: the
// particles ask for them while they predict (SegSlam3d::match_candidates), and the requests
// on copies of one segment are searched together, over the square that covers all of their
// regions (match_regions_unambiguous), each particle taking the answer for its own region.
//
// Why: a wide search costs tens of milliseconds (a branch and bound over +-10-25 m and
// +-0.5-1 rad, four ICP refinements), and the copies of one segment ask for several per
// update, from map-sample guesses a few metres apart, each covering most of the others'
// ground. The search does not depend on which particle asks or in which thread: the groups
// are formed in particle order, their region is the first member's rounded one grown to
// hold the others'.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <utility>

#include "lookahead/slam/segslam/seg_slam3d.hpp"

namespace lookahead::slam::segslam {

namespace {

// The region a request covers, rounded (guess to the wide stage's grid, reach to 1 m and
// 0.05 rad) so that particles with nearby guesses ask for the same one. The guess's grid is
// a whole number of the coarse search's steps (2.4 m for 2.5 m and 0.3 m steps), so that the
// coarse poses of particles searched together are those each would have searched alone: on
// grids shifted by a fraction of a step, ICP from the other grid's peak ends at other poses,
// and an alias one column spacing off may pass the tests.
WideRegion rounded_region(const Pose4& guess, const MatchingOptions& reach, const WideReentryOptions& w) {
  const LevelPoseGrid coarse = coarse_grid(reach);
  const auto lattice = [](double step, double unit) { return unit * std::max(1.0, std::round(step / unit)); };
  const double step = lattice(w.guess_step, coarse.step), angle_step = lattice(w.guess_angle_step, coarse.angle_step);
  const auto round_to = [](double v, double s) { return static_cast<double>(std::lround(v / s)) * s; };
  return {{round_to(guess.x, step), round_to(guess.y, step), round_to(guess.z, 0.5),
           normalize_angle(round_to(guess.yaw, angle_step))},
          static_cast<double>(std::lround(reach.search_radius)),
          static_cast<double>(std::lround(reach.search_angle / coarse.angle_step)) * coarse.angle_step};
}

}  // namespace

std::vector<SegSlam3d::WideSearch> SegSlam3d::wide_searches(const std::vector<const WideRequest*>& requests) const {
  const WideReentryOptions& w = options_.extras.wide;
  std::vector<WideSearch> out;
  // By (submap searched, height cell): the coarse search is level, at its centre's height.
  std::map<std::pair<std::size_t, long>, std::vector<std::size_t>> open;  // -> indices into out
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (!requests[i]) continue;
    const WideRequest& r = *requests[i];
    const std::size_t searched =
        options_.segslam.matching.share_by_segment ? segmap_.first_copy(r.candidate) : r.candidate;
    const WideRegion region = rounded_region(r.guess, r.options, w);
    std::vector<std::size_t>& groups = open[{searched, std::lround(region.centre.z / 0.5)}];
    // Joins the first search whose square stays within the stage's caps with it (a guess far
    // from the others would make the square, and its cost, grow).
    WideSearch* joined = nullptr;
    for (const std::size_t g : groups) {
      const WideRegion all = covering_subgrid(out[g].regions.front(), {region});
      if (all.radius <= std::max(w.max_radius, out[g].regions.front().radius) &&
          all.angle <= std::max(w.max_angle, out[g].regions.front().angle)) {
        joined = &out[g];
        break;
      }
    }
    if (!joined) {
      groups.push_back(out.size());
      joined = &out.emplace_back();
      joined->searched = searched;
      joined->options = r.options;
      joined->options.search_radius = region.radius;
      joined->options.search_angle = region.angle;
    }
    joined->members.push_back(i);
    joined->regions.push_back(region);
  }
  return out;
}

void SegSlam3d::run_wide_search(WideSearch& s, const SweepWindow& w) {
  const auto start = std::chrono::steady_clock::now();
  const std::shared_ptr<const OctreeMatchTarget> target = target_of(s.searched);
  s.results = match_regions_unambiguous(*target, window_with_structure(w), s.regions, s.options,
                                        options_.extras.structure, options_.extras.wide);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::lock_guard<std::mutex> lock(cache_mutex_);
  stats_.match_requests += s.members.size();
  ++stats_.match_attempts;
  ++stats_.wide_attempts;
  stats_.wide_matching_seconds += seconds;
  stats_.matching_seconds += seconds;
}

}  // namespace lookahead::slam::segslam
