// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/seg_slam.hpp"

#include <omp.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

#include "candidate_reach.hpp"
#include "compute_once.hpp"
#include "lookahead/slam/limits/input_limits.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"
#include "segmentation.hpp"
#include "submap_choice.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {

struct SegSlam::Transition {
  bool closed_one = false;
  GridSubmap closed;                ///< the submap the particle left, to store in the SegMap
  double closed_entry_error = 0.0;  ///< err_ICP of the match that opened `closed`
  std::size_t candidate = kNoSubmap;
  double weight = 0.0;
};

SegSlam::SegSlam(const RbpfOptions& rbpf, const SegSlamOptions& options)
    : rbpf_(rbpf),
      options_((validate(options), options)),
      motion_(rbpf.motion),
      prototype_grid_(rbpf.grid),
      likelihood_(rbpf.likelihood, prototype_grid_),
      matcher_(rbpf.matcher, likelihood_),
      rng_(mix_seed(rbpf.seed, 0x5E65E6ull, 0)) {}

void SegSlam::add_scan(const LaserScan& scan) {
  scans_.push_back(scan);
  ++stats_.scans;
  if (particles_.empty()) initialize();
  // SegSLAM sec. 4.1: the filter runs a look-ahead window behind the newest scan.
  while (next_pending_ < scans_.size() &&
         scans_.back().timestamp - scans_[next_pending_].timestamp >= options_.segmentation.lookahead_s) {
    const std::size_t k = next_pending_++;
    const Pose2 moved = scans_[last_update_].odometry.between(scans_[k].odometry);
    if (moved.norm() >= rbpf_.linear_update || std::abs(moved.theta) >= rbpf_.angular_update) update(k);
  }
}

void SegSlam::finish() {
  const double lookahead = options_.segmentation.lookahead_s;
  options_.segmentation.lookahead_s = 0.0;  // the window shrinks to what is left
  while (next_pending_ < scans_.size()) {
    const std::size_t k = next_pending_++;
    const Pose2 moved = scans_[last_update_].odometry.between(scans_[k].odometry);
    if (moved.norm() >= rbpf_.linear_update || std::abs(moved.theta) >= rbpf_.angular_update) update(k);
  }
  options_.segmentation.lookahead_s = lookahead;
}

void SegSlam::initialize() {
  const LaserScan& s = scans_.front();
  SegParticle p;
  p.pose = s.odometry;  // the first submap's frame is the odometry frame of the first scan
  p.submap.interval = {0, 0, s.timestamp, s.timestamp};
  p.submap.entry = p.submap.exit = p.pose;
  p.submap.map = prototype_grid_;
  insert_scan(p.submap.map, p.pose, s, rbpf_.insert);
  // Each particle copies the tiles a scan touches (copy-on-write): N times the first scan's.
  limits::check_memory(
      static_cast<double>(rbpf_.particles) * static_cast<double>(p.submap.map.tile_count()) * sizeof(GridTile),
      fmt::format("{} particles x {} map tiles of {} bytes", rbpf_.particles, p.submap.map.tile_count(),
                  sizeof(GridTile)));
  p.submap.path.push_back({0, p.pose});
  particles_.assign(static_cast<std::size_t>(rbpf_.particles), p);
  next_pending_ = 1;
  stats_.updates = 1;
  stats_.neff.push_back(static_cast<double>(rbpf_.particles));
}

LookaheadWindow SegSlam::window_after(std::size_t scan) const {
  LookaheadWindow w;
  const LaserScan& first = scans_[scan];
  std::vector<std::size_t> in{scan};
  for (std::size_t j = scan + 1;
       j < scans_.size() && scans_[j].timestamp - first.timestamp <= options_.segmentation.lookahead_s; ++j) {
    in.push_back(j);
  }
  Points2 points;
  const std::size_t every = std::max<std::size_t>(1, in.size() / 10);  // at most ~10 scans in the cloud
  for (std::size_t i = 0; i < in.size(); i += every) {
    const LaserScan& s = scans_[in[i]];
    const Pose2 laser = first.odometry.between(s.odometry).compose(s.laser_offset);
    for (std::size_t b = 0; b < s.ranges.size(); ++b) {
      if (!s.is_return(b) || s.ranges[b] > rbpf_.likelihood.max_range) continue;
      const Pose2 end = laser.compose({s.ranges[b] * std::cos(s.bearing(b)), s.ranges[b] * std::sin(s.bearing(b)), 0});
      points.emplace_back(end.x, end.y);
    }
  }
  w.cloud = bin_points(points, options_.matching.bin_size);
  const int n = options_.segmentation.predictive_scans;
  if (in.size() > 1) {
    for (int i = 1; i <= n; ++i) {
      const std::size_t j =
          in[std::min(in.size() - 1, (in.size() - 1) * static_cast<std::size_t>(i) / static_cast<std::size_t>(n))];
      w.scans.push_back(prepare_scan(scans_[j], rbpf_.likelihood));
      w.relative_poses.push_back(first.odometry.between(scans_[j].odometry));
    }
  }
  return w;
}

namespace {

// Matches are cached by their guess rounded to this [m] (and 0.1 rad): half the coarse
// search's reach, so the search from the rounded guess still covers the true pose.
constexpr double kGuessStep = 1.0;

// Distance from (x, y) to the nearest pose of a submap's own path [m].
double distance_to_path(const GridSubmap& s, double x, double y) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [scan, pose] : s.path) best = std::min(best, std::hypot(pose.x - x, pose.y - y));
  return best;
}

}  // namespace

std::vector<WindowMatch> SegSlam::match_candidates(const SegParticle& p, const LookaheadWindow& w,
                                                   std::vector<std::size_t>& ids, std::mt19937_64& rng) {
  const MatchingOptions& o = options_.matching;
  const double now = scans_[last_update_].timestamp;
  const auto sample = sample_local_map(segmap_, p.submap, kNoSubmap, o.sample_submaps, rng);
  const GridSubmap* own_root = frame_root(segmap_, p.submap);
  struct Candidate {
    double distance;
    std::size_t id;
    Pose2 guess;
    MatchingOptions reach;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 1; i < sample.size(); ++i) {
    // A merged submap's evidence is in its parent, which shares its frame.
    std::size_t id = sample[i].id;
    while (segmap_.at(id).merged) id = segmap_.at(id).parent;
    const GridSubmap& c = segmap_.at(id);
    if (std::any_of(candidates.begin(), candidates.end(), [&](const auto& k) { return k.id == id; })) continue;
    // SegSLAM sec. 4.5.1 winnowing: temporal separation, then spatial proximity. A submap in the
    // particle's own frame (already re-entered) is no candidate. Deviation: proximity is the
    // distance to the candidate's own path (the robot stood there), not any observed cell:
    // a laser sees far, and observed cells alone let through most of a building.
    if (c.interval.t_end > now - o.min_separation_s) continue;
    if (frame_root(segmap_, c)->interval == own_root->interval) continue;
    const Pose2 guess = sample[i].frame.inverse().compose(p.pose);
    const double d = distance_to_path(c, guess.x, guess.y);
    // Deviation (candidate_reach.hpp, as in 3D): the reach widens with the error since the
    // candidate was left: after a long loop the map sample's guess is metres off, beyond a
    // fixed 2 m search. Capped at max_search_radius (a wider search costs time, not error).
    const MatchingOptions reach = candidate_reach(o, error_since(id), o.max_search_radius);
    if (d > reach.proximity_radius || !has_observed_near(c.map, guess.x, guess.y, reach.proximity_radius)) continue;
    candidates.push_back({d, id, guess, reach});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  if (candidates.size() > static_cast<std::size_t>(o.max_candidates))
    candidates.resize(static_cast<std::size_t>(o.max_candidates));
  std::vector<WindowMatch> out;
  for (const Candidate& c : candidates) {
    WindowMatch m = screened_match(c.id, c.guess, w, c.reach);
    // The frame's first scan places the match against a reference trajectory.
    spdlog::debug(
        "scan {} candidate {} [{}-{}] frame {} guess ({:.2f} {:.2f} {:.2f}) -> ({:.2f} {:.2f} {:.2f}) err {:.3f} tau "
        "{:.2f} ok {} w {:.3f}",
        last_update_, c.id, segmap_.at(c.id).interval.first_scan, segmap_.at(c.id).interval.last_scan,
        frame_root(segmap_, segmap_.at(c.id))->interval.first_scan, c.guess.x, c.guess.y, c.guess.theta, m.pose.x,
        m.pose.y, m.pose.theta, m.icp_error, m.translation, m.ok, m.weight);
    if (!m.ok) continue;
    ids.push_back(c.id);
    out.push_back(m);
  }
  return out;
}

std::uint64_t SegSlam::localization_seed(const std::tuple<std::size_t, long, long, long>& key) const {
  // From the cache key, not the asking particle: the same match whatever the thread order.
  const auto [candidate, x, y, theta] = key;
  const std::uint64_t a = mix_seed(rbpf_.seed, stats_.updates, candidate);
  return mix_seed(a, static_cast<std::uint64_t>(x) * 0x1000003ull + static_cast<std::uint64_t>(y),
                  static_cast<std::uint64_t>(theta));
}

WindowMatch SegSlam::screened_match(std::size_t candidate, const Pose2& guess, const LookaheadWindow& w,
                                    const MatchingOptions& reach) {
  // Screened on the segment's first copy (MatchingOptions::share_by_segment): where that
  // finds nothing, so do the other copies; a match found there is fitted to this copy.
  const std::size_t first = options_.matching.share_by_segment ? segmap_.first_copy(candidate) : candidate;
  if (first != candidate) {
    WindowMatch screen = cached_match(first, guess, w, reach);
    if (!screen.ok) return screen;
  }
  return cached_match(candidate, guess, w, reach);
}

double SegSlam::error_since(std::size_t candidate) const {
  return motion_error_sum_.at(last_update_) - motion_error_sum_.at(segmap_.at(candidate).interval.last_scan);
}

WindowMatch SegSlam::cached_match(std::size_t candidate, const Pose2& guess, const LookaheadWindow& w,
                                  const MatchingOptions& reach) {
  const auto key = std::make_tuple(candidate, std::lround(guess.x / kGuessStep), std::lround(guess.y / kGuessStep),
                                   std::lround(guess.theta / 0.1));
  bool searched = false;
  WindowMatch m = compute_once(
      match_cache_, cache_mutex_, key,
      [&] {
        // Searched from the rounded guess, so the result does not depend on which particle asked
        // first (determinism under threads).
        const Pose2 rounded{std::get<1>(key) * kGuessStep, std::get<2>(key) * kGuessStep,
                            normalize_angle(std::get<3>(key) * 0.1)};
        if (options_.matching.use_localization_filter) {
          return localize_window(segmap_.at(candidate).map, w, rounded, reach, likelihood_, localization_seed(key));
        }
        const auto target = compute_once(match_targets_, cache_mutex_, candidate, [&] {
          MatchingOptions widest = options_.matching;  // the near field serves every reach up to the cap
          widest.search_radius = std::max(widest.search_radius, widest.max_search_radius);
          return std::make_shared<const GridMatchTarget>(
              match_target_of(segmap_.at(candidate).map, widest, likelihood_));
        });
        return match_window(segmap_.at(candidate).map, *target, w, rounded, reach);
      },
      &searched);
  if (searched) {
    const std::lock_guard<std::mutex> lock(cache_mutex_);
    ++stats_.match_attempts;
  }
  m.translation = std::hypot(m.pose.x - guess.x, m.pose.y - guess.y);
  m.weight = m.ok ? m.spread_factor * match_weight(m.icp_error, m.translation, reach) : 0.0;
  return m;
}

SegSlam::Transition SegSlam::predict_submap(SegParticle& p, const std::function<const LookaheadWindow&()>& window,
                                            std::mt19937_64& rng) {
  Transition t;
  const SegmentationOptions& so = options_.segmentation;
  // SegSLAM eq. (17) only where it can decide (a large enough submap, motion error below its bound).
  const bool score_it =
      p.submap_updates >= so.min_segment_updates && p.motion_error < so.max_motion_error && so.predictive_threshold > 0;
  const double score = score_it ? predictive_score(p.submap.map, p.pose, window(), likelihood_) : -1.0;
  const bool segment = should_segment(p.submap_updates, p.motion_error, score, so);
  std::vector<std::size_t> ids;
  std::vector<WindowMatch> matches;
  // Periodic matching runs at the same updates for every particle, so particles that share
  // a history ask for the same match in the same update and share it through the cache; like
  // the temporal-separation criterion, it does not start over in a submap just entered
  // (hysteresis, SegSLAM sec. 4.5.1).
  const int period = options_.matching.period_updates;
  const bool periodic = stats_.updates % static_cast<std::size_t>(period) == 0 && p.submap_updates >= period;
  if (segment || periodic) matches = match_candidates(p, window(), ids, rng);
  std::vector<double> weights;
  for (const WindowMatch& m : matches) weights.push_back(m.weight);
  const ChoiceDraw draw = draw_submap_choice(segment, weights, options_.matching, rng);  // SegSLAM eq. (3)
  if (draw.choice == SubmapChoice::kSame) return t;
  const LaserScan& at = scans_[last_update_];
  GridSubmap next;
  next.interval = {last_update_, last_update_, at.timestamp, at.timestamp};
  if (draw.choice == SubmapChoice::kNew) {
    next.map = prototype_grid_;  // a fresh frame, the particle at its origin
    insert_scan(next.map, Pose2{}, at, rbpf_.insert);
  } else {
    t.candidate = ids[draw.match];
    t.weight = matches[draw.match].weight;
    next.entry = matches[draw.match].pose;  // the pose in the candidate's frame
    next.parent = t.candidate;
    next.map = segmap_.at(t.candidate).map;  // copy-on-write: shares every tile until written
    const LockingOptions& lo = options_.locking;
    next.locked = lo.lock && matches[draw.match].icp_error <= lo.lock_max_error &&
                  segmap_.at(t.candidate).merged_visits >= lo.lock_min_merged_visits;
  }
  next.exit = next.entry;
  next.path.push_back({last_update_, next.entry});
  t.closed_one = true;
  t.closed = std::move(p.submap);
  t.closed_entry_error = p.entry_error;
  p.entry_error = t.candidate == kNoSubmap ? std::numeric_limits<double>::infinity() : matches[draw.match].icp_error;
  p.submap = std::move(next);
  p.pose = p.submap.entry;
  p.submap_updates = 0;
  p.motion_error = 0.0;
  return t;
}

void SegSlam::update(std::size_t k) {
  const Pose2 u = scans_[last_update_].odometry.between(scans_[k].odometry);
  // Built once, by the first particle that scores SegSLAM eq. (17) or matches: binning the window's
  // points was serial work at every update, where three in four do neither.
  std::once_flag window_once;
  LookaheadWindow w;
  const std::function<const LookaheadWindow&()> window = [&]() -> const LookaheadWindow& {
    std::call_once(window_once, [&] { w = window_after(last_update_); });
    return w;
  };
  const PreparedScan prepared = prepare_scan(scans_[k], rbpf_.likelihood);
  match_cache_.clear();
  const ParticleStepModels models{rbpf_, motion_, likelihood_, matcher_};
  const int n = static_cast<int>(particles_.size());
  std::vector<Transition> transitions(particles_.size());
  std::vector<double> gain(particles_.size(), 0.0);
  std::vector<char> warm(particles_.size(), 0), failed(particles_.size(), 0);
  const int threads = rbpf_.threads > 0 ? rbpf_.threads : omp_get_num_procs();
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    errors.run([&] {
      SegParticle& p = particles_[static_cast<std::size_t>(i)];
      std::mt19937_64 rng(mix_seed(rbpf_.seed, stats_.updates, static_cast<std::uint64_t>(i)));
      transitions[static_cast<std::size_t>(i)] = predict_submap(p, window, rng);
      const bool is_warm = p.submap_updates >= rbpf_.warmup_updates || p.submap.parent != kNoSubmap;
      const double before = p.log_weight;
      // A locked submap is localised in, never written (sec. 6).
      failed[static_cast<std::size_t>(i)] =
          p.submap.locked
              ? draw_particle(models, p.submap.map, p.pose, p.log_weight, u, prepared, is_warm, rng)
              : advance_particle(models, p.submap.map, p.pose, p.log_weight, u, scans_[k], prepared, is_warm, rng);
      gain[static_cast<std::size_t>(i)] = p.log_weight - before;
      warm[static_cast<std::size_t>(i)] = is_warm;
      p.submap.path.push_back({k, p.pose});
      p.submap.interval.last_scan = k;
      p.submap.interval.t_end = scans_[k].timestamp;
      p.submap.exit = p.pose;
      ++p.submap_updates;
      p.motion_error += motion_error_increment(u, options_.segmentation);
    });
  }
  errors.rethrow();
  // Deviation: a fresh submap has nothing to weigh its first scans against; it gets the mean
  // factor of the other particles, so starting a submap is neither rewarded nor punished.
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < gain.size(); ++i)
    if (warm[i]) sum += gain[i], ++count;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    if (!warm[i] && count > 0) particles_[i].log_weight += sum / count;
    if (transitions[i].closed_one) store_closed(particles_[i], transitions[i]);
  }
  stats_.match_failures += static_cast<std::size_t>(std::count(failed.begin(), failed.end(), 1));
  motion_error_sum_.resize(k + 1, 0.0);
  motion_error_sum_[k] = motion_error_sum_[last_update_] + motion_error_increment(u, options_.segmentation);
  last_update_ = k;
  ++stats_.updates;
  resample_if_needed();
  if (stats_.updates % 10 == 0) {
    std::vector<std::size_t> roots;
    for (const SegParticle& p : particles_) roots.push_back(p.submap.predecessor), roots.push_back(p.submap.parent);
    stats_.pruned += segmap_.prune(roots);
    for (auto it = match_targets_.begin(); it != match_targets_.end();) {
      it = segmap_.contains(it->first) ? std::next(it) : match_targets_.erase(it);
    }
  }
}

void SegSlam::store_closed(SegParticle& p, Transition& t) {
  const std::size_t parent = t.closed.parent;
  const std::size_t id = segmap_.add(std::move(t.closed));
  p.submap.predecessor = id;
  if (t.candidate == kNoSubmap) {
    ++stats_.segmentations;
  } else {
    ++stats_.matches;
    stats_.locked += p.submap.locked ? 1 : 0;
    stats_.match_events.push_back({last_update_, t.candidate, t.weight});
  }
  // SegSLAM sec. 6: a re-entry registered well enough is merged into the submap it matched, so
  // repeated traversals add no maps (a locked one adds no evidence either).
  if (!options_.locking.merge || parent == kNoSubmap || t.closed_entry_error > options_.locking.merge_max_error) return;
  if (segmap_.merge_into_parent(id, add_child_evidence)) {
    ++stats_.merged;
    match_targets_.erase(parent);  // its map changed
  }
}

// SegSLAM eq. (6)-(7): the RBPF's selective resampling (Grisetti et al. 2007, sec. IV step 5); a
// resampled particle shares its submap chain with its parent.
void SegSlam::resample_if_needed() {
  shift_log_weights(particles_);
  bool resampled = false;
  stats_.neff.push_back(resample_if_degenerate(particles_, rbpf_.resample_threshold, rng_, resampled));
  if (resampled) ++stats_.resamplings;
}

std::size_t SegSlam::best_particle() const { return best_particle_index(particles_); }

std::vector<std::pair<std::size_t, Pose2>> SegSlam::trajectory(std::size_t m) const {
  const auto chain = temporal_chain(segmap_, particles_.at(m).submap);
  return reconstruct_trajectory(chain, chain_frames_with_matches(segmap_, chain));
}

std::vector<Pose2> SegSlam::trajectory_at_every_scan(std::size_t m) const {
  return poses_at_every_scan(trajectory(m), scans_.size(), [&](std::size_t from, std::size_t to) {
    return scans_[from].odometry.between(scans_[to].odometry);
  });
}

Pose2 SegSlam::global_pose(std::size_t m) const {
  const auto chain = temporal_chain(segmap_, particles_.at(m).submap);
  return chain_frames_with_matches(segmap_, chain).back().compose(particles_[m].pose);
}

Pose2 SegSlam::estimate() const {
  const Pose2 mean = weighted_mean_pose(particle_weights(particles_), [&](std::size_t m) { return global_pose(m); });
  return mean.compose(scans_[last_update_].odometry.between(scans_.back().odometry));
}

}  // namespace lookahead::slam::segslam
