// SPDX-License-Identifier: MIT
// SegSLAM 3D's matching step (Fairfield et al. 2010, SegSLAM sec. 4.5): the candidates of a particle's
// local map sample, winnowed (SegSLAM sec. 4.5.1), matched (SegSLAM sec. 4.5.2: the capped search of
// candidate_reach.hpp, then the wide unambiguous search of wide_reentry.hpp) and weighted by
// SegSLAM eq. (18) (or SegSLAM eq. (19): localization_match3.hpp). Both searches are asked for here and run for
// all particles together: the capped ones before the particles draw (seg_slam3d_capped.cpp),
// the wide ones after (seg_slam3d_wide.cpp). Split out of seg_slam3d.cpp, whose filter loop
// calls it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "candidate_reach.hpp"
#include "localization_match3.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/segslam/seg_slam3d.hpp"
#include "lookahead/slam/segslam/wide_reentry.hpp"
#include "seg_slam3d_transition.hpp"
#include "submap_choice.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Distance in the plane from p to the nearest pose of a submap's path, if one is within
// `height` of p's height [m].
double distance_to_path(const OctreeSubmap& s, const Pose4& p, double height) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [sweep, q] : s.path) {
    if (std::abs(q.z - p.z) <= height) best = std::min(best, std::hypot(q.x - p.x, q.y - p.y));
  }
  return best;
}

}  // namespace

const SweepWindow& SegSlam3d::window_with_structure(const SweepWindow& w) {
  const std::lock_guard<std::mutex> lock(window_mutex_);
  if (!matched_window_) {
    matched_window_ = w;
    find_structure(*matched_window_, options_.segslam.matching);
  }
  return *matched_window_;
}

void SegSlam3d::ask_matches(SegParticle3& p, const SweepWindow& w, Transition& t, std::mt19937_64& rng) {
  // Last attempt's wide re-entry, offered if this window confirms it.
  const std::optional<std::size_t> pending = p.pending ? std::optional(p.pending->candidate) : std::nullopt;
  const Pose4 pending_guess = p.pending ? p.pending->guess_frame.compose(p.pose) : Pose4{};
  if (const std::optional<WindowMatch3> m = confirm_pending(p, w, t.attempts)) {
    t.ids.push_back(*pending);
    t.guesses.push_back(pending_guess);
    t.matches.push_back(*m);
    // Confirmed, it stays pending at the confirmed pose: offered again at every attempt
    // whose window confirms it, until taken or contradicted.
    p.pending = pending_of(*pending, m->pose, pending_guess, p.pose);
    t.pending_weight = m->weight;
  }
  t.candidates = winnow(p, t.ids.empty() ? kNoSubmap : t.ids.front(), t.attempts, rng);
  t.screens.assign(t.candidates.size(), WindowMatch3{});
}

void SegSlam3d::collect_matches(SegParticle3& p, const SweepWindow& w, Transition& t) {
  const bool record = options_.extras.record_attempts;
  bool wide_searched = false;
  for (std::size_t k = 0; k < t.candidates.size(); ++k) {
    const Candidate& c = t.candidates[k];
    WindowMatch3 m;
    if (!c.wide_only) m = capped_result(c, t.screens[k], w);
    // The wide stage where the capped search found nothing and the candidate's uncertainty
    // reaches beyond it; for the nearest such candidate only (the stage is costly).
    if (!m.ok && !wide_searched && c.wide.has_value()) {
      // Run after this update's predictions, with the other particles' of the segment
      // (seg_slam3d_wide.cpp); its result is never offered at this attempt anyway.
      t.wide = WideRequest{c.id, c.guess, *c.wide, c.attempt, t.pending_weight, p.pose, std::nullopt, false};
      wide_searched = true;
      continue;
    }
    if (record) this->record(t.attempts[c.attempt], c.id, m, false);
    if (!m.ok) continue;
    t.ids.push_back(c.id);
    t.guesses.push_back(c.guess);
    t.matches.push_back(m);
  }
}

void SegSlam3d::record(MatchAttempt3& a, std::size_t candidate, const WindowMatch3& m, bool wide) const {
  a.outcome = !m.ok ? AttemptOutcome::kRejected : wide ? AttemptOutcome::kPending : AttemptOutcome::kOffered;
  a.guess_score = m.guess_score, a.coarse_score = m.coarse_score, a.pose = m.pose, a.rejection = m.rejection;
  a.match_path_distance = distance_to_path(segmap_.at(candidate), m.pose, options_.extras.proximity_height);
  a.wide = wide, a.modes = m.modes;
}

void SegSlam3d::apply_wide(SegParticle3& p, const WideRequest& r, WindowMatch3 m,
                           std::vector<MatchAttempt3>& attempts) {
  m.translation = (m.pose.position() - r.guess.position()).norm();
  m.weight = m.ok ? match_weight(m.icp_error, m.translation, candidate_options(r.candidate)) : 0.0;
  // A wide pose farther from this particle's guess than the reach (the search started from
  // a rounded guess, and ICP moves) is outside the region its uncertainty allows: such
  // poses were aliases one column spacing off.
  if (m.ok && m.translation > r.options.search_radius) m.ok = false, m.weight = 0.0, m.rejection = "beyond reach";
  if (options_.extras.record_attempts) record(attempts[r.attempt], r.candidate, m, true);
  if (!m.ok || r.dropped) return;
  // Not offered yet: the next attempt checks it (wide_reentry.hpp); it replaces a confirmed
  // one only if heavier by SegSLAM eq. (18). Placed as at the request, then carried as the pending
  // re-entry would have been.
  PendingReentry found = pending_of(r.candidate, m.pose, r.guess, r.pose);
  if (r.carried) found = carried_into(found, *r.carried);
  if (!p.pending || m.weight > r.pending_weight) p.pending = found;
}

std::vector<SegSlam3d::Candidate> SegSlam3d::winnow(const SegParticle3& p, std::size_t skip,
                                                    std::vector<MatchAttempt3>& attempts, std::mt19937_64& rng) const {
  const MatchingOptions& o = options_.segslam.matching;
  const double now = sweeps_[last_update_].time;
  const auto sample = sample_local_map(segmap_, p.submap, kNoSubmap, o.sample_submaps, rng);
  const OctreeSubmap* own_root = frame_root(segmap_, p.submap);
  const std::vector<double> chain = chain_errors(sample, p);
  std::vector<Candidate> candidates;
  for (std::size_t i = 1; i < sample.size(); ++i) {
    // A merged submap's evidence is in its parent, which shares its frame (locking.merge:
    // seg_slam3d_locking.cpp); the match is to the parent. Without merging, id is sample[i].id.
    const std::size_t id = map_holder(sample[i].id);
    if (id == skip) continue;  // a pending re-entry, confirmed
    if (std::any_of(candidates.begin(), candidates.end(), [&](const Candidate& k) { return k.id == id; })) continue;
    const OctreeSubmap& c = segmap_.at(id);
    // SegSLAM sec. 4.5.1 winnowing as in 2D: temporal separation, not the particle's own frame,
    // and (Deviation, as in 2D) near the candidate's own path, here also in height.
    if (c.interval.t_end > now - o.min_separation_s) continue;
    if (frame_root(segmap_, c)->interval == own_root->interval) continue;
    const Pose4 guess = sample[i].frame.inverse().compose(p.pose);
    // Deviation (3D only; 2D takes the parent's path): the merged submap's path counts too,
    // since the robot stood there and what it saw is now in c.
    const double d = std::min(distance_to_path(c, guess, options_.extras.proximity_height),
                              distance_to_path(segmap_.at(sample[i].id), guess, options_.extras.proximity_height));
    const double radius = candidate_options(id).proximity_radius;
    const std::optional<MatchingOptions> wide = wide_options(chain[i]);
    const bool near = d <= radius && has_observed_near(c.map, guess.position(), radius);
    const bool near_wide = !near && wide && d <= wide->proximity_radius &&
                           has_observed_near(c.map, guess.position(), wide->proximity_radius);
    if (options_.extras.record_attempts) {
      attempts.push_back(attempt_of(id, guess, d, chain[i], wide));
      const bool far = d > (wide ? wide->proximity_radius : radius);
      attempts.back().outcome = near || near_wide ? AttemptOutcome::kNotNearest
                                : far             ? AttemptOutcome::kFar
                                                  : AttemptOutcome::kUnobserved;
    }
    if (!near && !near_wide) continue;
    candidates.push_back({near_wide, wide, d, id, guess, attempts.size() - 1});
  }
  // Those within the capped reach first, as before the wide stage: it only fills free places.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.wide_only != b.wide_only ? b.wide_only : a.distance < b.distance;
  });
  if (candidates.size() > static_cast<std::size_t>(o.max_candidates))
    candidates.resize(static_cast<std::size_t>(o.max_candidates));
  return candidates;
}

WindowMatch3 SegSlam3d::capped_result(const Candidate& c, WindowMatch3 screen, const SweepWindow& w) {
  // Screened on the segment's first copy (MatchingOptions::share_by_segment): where that
  // finds nothing, so do the others; a match found there is fitted again to this copy.
  const std::size_t first = options_.segslam.matching.share_by_segment ? segmap_.first_copy(c.id) : c.id;
  if (first != c.id && screen.ok) return cached_match(c.id, c.guess, w);
  const MatchingOptions o = candidate_options(c.id);
  screen.translation = (screen.pose.position() - c.guess.position()).norm();
  screen.weight = screen.ok ? screen.spread_factor * match_weight(screen.icp_error, screen.translation, o) : 0.0;
  return screen;
}

LevelSubgrid SegSlam3d::capped_region(const Pose4& guess, const MatchingOptions& reach) {
  const LevelPoseGrid coarse = coarse_grid(reach);
  const double step = 2 * coarse.step, angle_step = 2 * coarse.angle_step;
  const auto round_to = [](double v, double s) { return static_cast<double>(std::lround(v / s)) * s; };
  return {{round_to(guess.x, step), round_to(guess.y, step), round_to(guess.z, 0.5),
           normalize_angle(round_to(guess.yaw, angle_step))},
          reach.search_radius,
          reach.search_angle};
}

WindowMatch3 SegSlam3d::cached_match(std::size_t candidate, const Pose4& guess, const SweepWindow& w) {
  const MatchingOptions o = candidate_options(candidate);
  // Searched from the rounded guess: the result does not depend on which particle asked.
  const LevelSubgrid region = capped_region(guess, o);
  const MatchKey key = key_of(candidate, region);
  WindowMatch3 m;
  bool found = false;
  {
    const std::lock_guard<std::mutex> lock(cache_mutex_);
    ++stats_.match_requests;
    const auto it = match_cache_.find(key);
    if (it != match_cache_.end()) m = it->second, found = true;
  }
  if (!found) {
    const auto start = std::chrono::steady_clock::now();
    m = capped_search(candidate, region, o, w);
    const std::lock_guard<std::mutex> lock(cache_mutex_);
    match_cache_.emplace(key, m);
    ++stats_.match_attempts;
    stats_.matching_seconds += seconds_since(start);
  }
  m.translation = (m.pose.position() - guess.position()).norm();
  m.weight = m.ok ? m.spread_factor * match_weight(m.icp_error, m.translation, o) : 0.0;
  return m;
}

WindowMatch3 SegSlam3d::capped_search(std::size_t candidate, const LevelSubgrid& region, const MatchingOptions& o,
                                      const SweepWindow& w) {
  // SegSLAM sec. 4.5.2: SegSLAM eq. (18) (coarse search and ICP) or the localisation filter of SegSLAM eq. (19).
  if (o.use_localization_filter) {
    return localize_window3(segmap_.at(candidate).map, *target_of(candidate), window_with_structure(w), region.centre,
                            o, options_.filter.likelihood, options_.extras.structure,
                            localization_seed(key_of(candidate, region)));
  }
  return match_window(*target_of(candidate), window_with_structure(w), region.centre, o, options_.extras.structure);
}

SegSlam3d::MatchKey SegSlam3d::key_of(std::size_t candidate, const LevelSubgrid& region) {
  // The region's centre is on the lattice: to the millimetre and the 1e-4 rad it names it.
  return {candidate, std::lround(region.centre.x * 1e3), std::lround(region.centre.y * 1e3),
          std::lround(region.centre.z * 1e3), std::lround(region.centre.yaw * 1e4)};
}

std::uint64_t SegSlam3d::localization_seed(const MatchKey& key) const {
  // From the cache key, not the asking particle: the same match whatever the thread order.
  const auto [candidate, x, y, z, yaw] = key;
  const std::uint64_t a = mix_seed(options_.filter.seed, stats_.updates, candidate);
  return mix_seed(a, static_cast<std::uint64_t>(x) * 0x1000003ull + static_cast<std::uint64_t>(y),
                  static_cast<std::uint64_t>(z) * 0x10001ull + static_cast<std::uint64_t>(yaw));
}

MatchingOptions SegSlam3d::candidate_options(std::size_t candidate) const {
  // Deviation (candidate_reach.hpp): SegSLAM eq. (18)'s p(tau^2), the proximity radius and the coarse
  // search widen with the SegSLAM eq. (13)-(14) error accumulated since the candidate was left, as
  // SegSLAM sec. 4.5.2 spreads the localisation filter ("candidate positions at the end of long
  // loops will be uncertain"): a fixed sigma and search miss re-entries after a long loop.
  return candidate_reach(options_.segslam.matching, error_since(candidate),
                         options_.segslam.matching.max_search_radius);
}

std::shared_ptr<const OctreeMatchTarget> SegSlam3d::target_of(std::size_t candidate) {
  {
    const std::lock_guard<std::mutex> lock(cache_mutex_);
    if (auto t = targets_[candidate]) return t;
  }
  auto t =
      std::make_shared<const OctreeMatchTarget>(match_target_of(segmap_.at(candidate).map, options_.segslam.matching));
  const std::lock_guard<std::mutex> lock(cache_mutex_);
  targets_[candidate] = t;
  return t;
}

std::optional<WindowMatch3> SegSlam3d::confirm_pending(SegParticle3& p, const SweepWindow& w,
                                                       std::vector<MatchAttempt3>& attempts) {
  const std::optional<PendingReentry> pending = std::exchange(p.pending, std::nullopt);
  if (!pending || !segmap_.contains(pending->candidate)) return std::nullopt;
  // Matched from where the pending re-entry puts the robot now, by a coarse search of twice
  // the confirmation's tolerance (ICP alone from there fitted the structure less well: eq.
  // 18 errors 0.07-0.11 m against 0.03-0.06 m), and the same tests.
  const auto start = std::chrono::steady_clock::now();
  const Pose4 predicted = pending->frame.compose(p.pose);
  const Pose4 guess = pending->guess_frame.compose(p.pose);
  MatchingOptions o = candidate_options(pending->candidate);
  o.search_radius = 2 * options_.extras.wide.confirm_distance;
  o.search_angle = 2 * options_.extras.wide.confirm_angle;
  WindowMatch3 m =
      match_window(*target_of(pending->candidate), window_with_structure(w), predicted, o, options_.extras.structure);
  m.translation = (m.pose.position() - guess.position()).norm();
  m.weight = m.ok ? match_weight(m.icp_error, m.translation, o) : 0.0;
  if (m.ok && !confirms(predicted, m.pose, options_.extras.wide))
    m.ok = false, m.weight = 0.0, m.rejection = "unconfirmed";
  {
    const std::lock_guard<std::mutex> lock(cache_mutex_);
    stats_.matching_seconds += seconds_since(start);
  }
  if (options_.extras.record_attempts) {
    MatchAttempt3 a = attempt_of(
        pending->candidate, guess,
        distance_to_path(segmap_.at(pending->candidate), guess, options_.extras.proximity_height), 0.0, std::nullopt);
    a.outcome = m.ok ? AttemptOutcome::kOffered : AttemptOutcome::kRejected;
    a.pose = m.pose, a.rejection = m.rejection, a.confirmation = true;
    a.guess_score = m.guess_score, a.coarse_score = m.coarse_score;
    a.match_path_distance = distance_to_path(segmap_.at(pending->candidate), m.pose, options_.extras.proximity_height);
    attempts.push_back(std::move(a));
  }
  if (!m.ok) return std::nullopt;
  return m;
}

double SegSlam3d::error_since(std::size_t candidate) const {
  return motion_error_sum_.at(last_update_) - motion_error_sum_.at(segmap_.at(candidate).interval.last_scan);
}

std::optional<MatchingOptions> SegSlam3d::wide_options(double chain_error) const {
  // Deviation (wide_reentry.hpp): beyond the capped search, a second stage sized by SegSLAM eq. (18)'s
  // sigma_tau, accepted only when one pose of it passes the tests (SegSLAM eq. (19)'s covariance term).
  return wide_reach(options_.segslam.matching, chain_error, options_.segslam.matching.max_search_radius,
                    options_.extras.wide);
}

std::vector<double> SegSlam3d::chain_errors(const std::vector<PlacedSubmap<Pose4>>& sample,
                                            const SegParticle3& p) const {
  // SegSLAM sec. 4.5.2: "each transformation in the local map sampling process adds some
  // uncertainty". A placed frame's is the SegSLAM eq. (13)-(14) error along the links that composed it:
  // the particle's own in its open submap, then per link the error inside the submap the
  // link's transform spans (a predecessor's entry-to-exit, or the submap left through its
  // exit), none across a match (the same frame). A re-entry the particle took shortens the
  // chain; the time since the candidate (candidate_reach's measure) does not see it, and with
  // it the wide stage ran where the capped search sufficed.
  const auto inside = [&](std::size_t id) {
    const Interval& in = segmap_.at(id).interval;
    return motion_error_sum_.at(in.last_scan) - motion_error_sum_.at(in.first_scan);
  };
  std::vector<double> out(sample.size(), p.motion_error);
  for (std::size_t k = 1; k < sample.size(); ++k) {
    const PlacedSubmap<Pose4>& s = sample[k];
    double step = 0.0;
    if (s.link == 0) step = inside(s.id);
    if (s.link == 1) step = s.from == 0 ? p.motion_error : inside(sample[s.from].id);
    out[k] = out[s.from] + step;
  }
  return out;
}

MatchEvent3 SegSlam3d::offer_of(std::size_t candidate, const Pose4& guess, const WindowMatch3& m) const {
  MatchEvent3 e;
  e.sweep = last_update_, e.candidate = candidate, e.weight = m.weight;
  e.icp_error = m.icp_error, e.all_points_error = m.all_points_error;
  e.translation = m.translation, e.pose = m.pose, e.guess = guess;
  e.structure = m.structure;
  std::tie(e.reference_sweep, e.reference) = nearest_path_pose(candidate, m.pose.position());
  return e;
}

std::pair<std::size_t, Pose4> SegSlam3d::nearest_path_pose(std::size_t candidate, const Eigen::Vector3d& p) const {
  double best = std::numeric_limits<double>::infinity();
  std::pair<std::size_t, Pose4> out{0, Pose4{}};
  // The candidate's ancestors share its frame (a match child copies its parent's).
  for (std::size_t id = candidate; id != kNoSubmap && segmap_.contains(id); id = segmap_.at(id).parent) {
    for (const auto& [sweep, q] : segmap_.at(id).path) {
      const double d = (q.position() - p).norm();
      if (d < best) best = d, out = {sweep, q};
    }
  }
  return out;
}

MatchAttempt3 SegSlam3d::attempt_of(std::size_t candidate, const Pose4& guess, double path_distance, double chain_error,
                                    const std::optional<MatchingOptions>& wide) const {
  MatchAttempt3 a;
  a.sweep = last_update_, a.candidate = candidate, a.guess = guess, a.path_distance = path_distance;
  const MatchingOptions o = candidate_options(candidate);
  a.proximity_radius = o.proximity_radius;
  a.search_radius = o.search_radius;
  a.search_angle = o.search_angle;
  a.error_since = error_since(candidate);
  a.chain_error = chain_error;
  if (wide) {
    a.wide_proximity_radius = wide->proximity_radius;
    a.wide_search_radius = wide->search_radius;
    a.wide_search_angle = wide->search_angle;
  }
  std::tie(a.reference_sweep, a.reference) = nearest_path_pose(candidate, guess.position());
  for (std::size_t id = candidate; id != kNoSubmap && segmap_.contains(id); id = segmap_.at(id).parent) {
    a.intervals.emplace_back(segmap_.at(id).interval.first_scan, segmap_.at(id).interval.last_scan);
  }
  return a;
}

}  // namespace lookahead::slam::segslam
