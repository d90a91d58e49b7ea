// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/wide_reentry.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

bool same_mode(const Pose4& a, const Pose4& b, const WideReentryOptions& w) {
  return std::hypot(a.x - b.x, a.y - b.y) <= w.separation &&
         std::abs(normalize_angle(a.yaw - b.yaw)) <= w.angle_separation;
}

}  // namespace

void validate(const WideReentryOptions& w) {
  if (!(w.max_radius >= 0) || !(w.sigmas > 0) || !(w.angle_per_error >= 0) || !(w.max_angle >= 0) || w.peaks < 2 ||
      !(w.separation > 0) || !(w.angle_separation > 0) || !(w.confirm_distance > 0) || !(w.confirm_angle > 0) ||
      !(w.trigger_sigmas > 0 && w.trigger_sigmas <= w.sigmas) || !(w.guess_step > 0) || !(w.guess_angle_step > 0)) {
    throw std::invalid_argument(
        "segslam3d wide re-entry: max_radius >= 0, sigmas > 0, angle_per_error >= 0, max_angle >= 0, peaks >= 2, "
        "0 < trigger_sigmas <= sigmas, separation, angle_separation, confirm_distance, confirm_angle, guess_step and "
        "guess_angle_step > 0");
  }
}

PendingReentry pending_of(std::size_t candidate, const Pose4& match, const Pose4& guess, const Pose4& pose) {
  const Pose4 to_submap = pose.inverse();
  return {candidate, match.compose(to_submap), guess.compose(to_submap)};
}

PendingReentry carried_into(const PendingReentry& p, const Pose4& origin) {
  return {p.candidate, p.frame.compose(origin), p.guess_frame.compose(origin)};
}

bool confirms(const Pose4& predicted, const Pose4& found, const WideReentryOptions& w) {
  return std::hypot(found.x - predicted.x, found.y - predicted.y) <= w.confirm_distance &&
         std::abs(normalize_angle(found.yaw - predicted.yaw)) <= w.confirm_angle;
}

std::optional<MatchingOptions> wide_reach(const MatchingOptions& base, double error_since, double narrow_cap,
                                          const WideReentryOptions& w) {
  if (w.max_radius <= 0) return std::nullopt;
  const double e = std::max(0.0, error_since);
  const double sigma_tau = std::hypot(base.translation_sigma, e);
  // Only beyond the capped search: below it the narrow stage reaches as far, and its results
  // stay as they were.
  if (std::min(w.max_radius, w.trigger_sigmas * sigma_tau) <= std::max(narrow_cap, base.search_radius))
    return std::nullopt;
  const double reach = std::min(w.max_radius, w.sigmas * sigma_tau);
  MatchingOptions o = base;
  o.translation_sigma = sigma_tau;
  o.search_radius = reach;
  o.search_angle =
      std::max(base.search_angle, std::min(w.max_angle, std::hypot(base.search_angle, w.angle_per_error * e)));
  o.proximity_radius = base.proximity_radius + (reach - base.search_radius);
  return o;
}

WindowMatch3 match_window_unambiguous(const OctreeMatchTarget& target, const SweepWindow& window, const Pose4& guess,
                                      const MatchingOptions& o, const StructureTestOptions& so,
                                      const WideReentryOptions& wide) {
  return match_regions_unambiguous(target, window, {{guess, o.search_radius, o.search_angle}}, o, so, wide).front();
}

namespace {

// match_window_unambiguous's decision for one region among its peaks, refined.
WindowMatch3 unambiguous_in(const WideRegion& region, const std::vector<LevelCoarseResult>& peaks,
                            const std::function<const WindowMatch3&(const Pose4&)>& refined,
                            const OctreeMatchTarget& target, const SweepWindow& window, const MatchingOptions& o,
                            const WideReentryOptions& wide) {
  WindowMatch3 out;
  out.rejection = "no peak";
  const double guess_score = share_of(near_in_plane_count(target.field, region.centre, window.scored), window.scored);
  std::vector<WindowMatch3> passed;
  for (std::size_t k = 0; k < peaks.size(); ++k) {
    WindowMatch3 m = refined(peaks[k].pose);
    m.translation = (m.pose.position() - region.centre.position()).norm();
    m.weight = m.ok ? match_weight(m.icp_error, m.translation, o) : 0.0;
    m.guess_score = guess_score;
    m.coarse_score = share_of(peaks[k].score, window.scored);
    if (k == 0) out = m;  // what is reported when nothing passes
    if (!m.ok) continue;
    // ICP from two peaks may converge to one pose: one mode, kept once (the better fit).
    const auto same = std::find_if(passed.begin(), passed.end(),
                                   [&](const WindowMatch3& p) { return same_mode(p.pose, m.pose, wide); });
    if (same == passed.end()) {
      passed.push_back(m);
    } else if (m.icp_error < same->icp_error) {
      *same = m;
    }
    // Two distinct passing poses decide it (ambiguous): the remaining peaks' ICP and tests
    // would change only the rejected match's reported pose and mode count.
    if (passed.size() > 1) break;
  }
  if (passed.empty()) return out;
  WindowMatch3 best = passed.front();
  for (const WindowMatch3& m : passed) {
    if (m.icp_error < best.icp_error) best = m;
  }
  best.modes = passed.size();
  if (passed.size() > 1) {
    best.ok = false;
    best.weight = 0.0;
    best.rejection = "ambiguous";
  }
  return best;
}

}  // namespace

std::vector<WindowMatch3> match_regions_unambiguous(const OctreeMatchTarget& target, const SweepWindow& window,
                                                    const std::vector<WideRegion>& regions, const MatchingOptions& o,
                                                    const StructureTestOptions& so, const WideReentryOptions& wide) {
  WindowMatch3 few;
  few.rejection = "too few points";
  std::vector<WindowMatch3> out(regions.size(), few);
  if (regions.empty() || target.icp.size() < 10 || window.cloud.size() < 10) return out;
  const std::vector<std::vector<LevelCoarseResult>> peaks =
      region_peaks(target, window, regions, o, wide.peaks, wide.separation, wide.angle_separation);
  // Each distinct grid pose is refined once (only tau and the weight depend on the guess, and
  // unambiguous_in takes them again per region).
  std::vector<Pose4> seeds;
  for (const auto& own : peaks) {
    for (const LevelCoarseResult& p : own) seeds.push_back(p.pose);
  }
  const RefinedMatches refined = refine_each(target, window, seeds, o, so);
  const auto refine = [&](const Pose4& seed) -> const WindowMatch3& {
    return refined.at(std::make_tuple(seed.x, seed.y, seed.z, seed.yaw));
  };
  for (std::size_t r = 0; r < regions.size(); ++r)
    out[r] = unambiguous_in(regions[r], peaks[r], refine, target, window, o, wide);
  return out;
}

}  // namespace lookahead::slam::segslam
