// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/seg_slam3d.hpp"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "lookahead/slam/octree/octree_likelihood.hpp"
#include "lookahead/slam/octree/ray_insertion.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/rbpf3d/motion3_model.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "seg_slam3d_transition.hpp"
#include "segmentation.hpp"
#include "submap_choice.hpp"
#include "trajectory_reconstruction.hpp"

namespace lookahead::slam::segslam {

SegSlamOptions segslam3d_defaults() {
  SegSlamOptions o;
  // One sweep per second: 3 s of look-ahead is three sweeps, a segment at least 10 m.
  o.segmentation.lookahead_s = 3.0;
  o.segmentation.min_segment_updates = 10;
  // Bins of one voxel (0.2 m).
  o.matching.bin_size = 0.2;
  o.matching.icp_iterations = 20;
  o.matching.icp_max_distance = 0.5;
  // SegSLAM eq. (18) on the structure points' error (match_window): right re-entries on the
  // garage show 0.02-0.1 m.
  o.matching.icp_sigma = 0.05;
  o.matching.null_error = 0.08;
  o.matching.proximity_radius = 4.0;
  // The map sample's guess may be over 0.3 rad off in yaw at a loop's closure: the coarse
  // search must reach that far.
  o.matching.search_angle = 0.4;
  o.offline.map_samples = 5;
  // The best particle's chain as a map candidate (on in 2D) is off: on the garage loop it wins
  // the entropy search with a path further from the truth than the samples'.
  o.offline.particle_chain = false;
  // The paper's segmentation (the 2D defaults changed for the scan-matching proposal): the
  // garage's sweeps weigh by ray casting, and its studies ran with these.
  o.segmentation.max_motion_error = 1.0;
  o.segmentation.predictive_threshold = 0.5;
  o.segmentation.slam_factor = 0.5;
  o.matching.max_search_radius = 6.0;  // beyond it the wide stage (wide_reentry.hpp)
  return o;
}

/// Dead reckoning from the last update's sweep to this one, and this sweep's beams.
struct SegSlam3d::SweepModel {
  Pose3 increment;
  Euler imu_before, imu;
  double yaw_change = 0.0;
  std::vector<Eigen::Vector3d> ends;  ///< scored end points, robot frame
  std::vector<Ray3> rays;             ///< inserted beams, robot frame
  std::size_t sweep = 0;
  double motion_error = 0.0;  ///< SegSLAM eq. (13)-(14) increment [m]
};

namespace {

// The sweep's beams (every n-th) in the submap frame with the robot at `pose`.
std::vector<Ray3> rays_at(const Pose3& pose, const std::vector<Ray3>& local) {
  std::vector<Ray3> out(local.size());
  for (std::size_t k = 0; k < local.size(); ++k) out[k] = {pose * local[k].origin, pose * local[k].end, local[k].hit};
  return out;
}

}  // namespace

SegSlam3d::SegSlam3d(const SegSlam3dOptions& options)
    : options_(options), rng_(mix_seed(options.filter.seed, 0x5E653Dull, 0)) {
  options_.filter.validate();
  validate(options_.segslam);
  const SegSlam3dExtras& e = options_.extras;
  if (e.warmup_updates < 0 || !(e.proximity_height > 0) || e.window_points < 10) {
    throw std::invalid_argument("segslam3d: warmup_updates >= 0, proximity_height > 0, window_points >= 10");
  }
  validate(e.wide);
  if (!(e.structure.min_inlier_ratio >= 0 && e.structure.min_inlier_ratio <= 1) ||
      !(e.structure.max_free_ratio >= 0 && e.structure.max_free_ratio <= 1)) {
    throw std::invalid_argument("segslam3d: structure.min_inlier_ratio and max_free_ratio in 0..1");
  }
}

int SegSlam3d::thread_count() const {
  return options_.filter.threads > 0 ? options_.filter.threads : omp_get_num_procs();
}

void SegSlam3d::add_sweep(const RangeSweep& sweep) {
  sweeps_.push_back(sweep);
  ++stats_.sweeps;
  if (particles_.empty()) initialize(sweep);
  run_pending(options_.segslam.segmentation.lookahead_s);
}

void SegSlam3d::finish() { run_pending(0.0); }

void SegSlam3d::run_pending(double lookahead_s) {
  // SegSLAM sec. 4.1: the filter runs a look-ahead window behind the newest sweep.
  while (next_pending_ < sweeps_.size() && sweeps_.back().time - sweeps_[next_pending_].time >= lookahead_s) {
    update(next_pending_++);
  }
}

void SegSlam3d::initialize(const RangeSweep& first) {
  SegParticle3 p;
  p.pose = Pose4::level_of(first.odometry);  // the first submap's frame is the odometry frame
  p.submap.interval = {0, 0, first.time, first.time};
  p.submap.entry = p.submap.exit = p.pose;
  p.submap.map = EvidenceOctree(options_.filter.map);
  insert_rays(p.submap.map, rays_at(first.odometry, first.rays), options_.filter.insert);
  p.submap.path.push_back({0, p.pose});
  particles_.assign(static_cast<std::size_t>(options_.filter.particles), p);
  next_pending_ = 1;
  motion_error_sum_.assign(1, 0.0);
  stats_.updates = 1;
  stats_.neff.push_back(static_cast<double>(options_.filter.particles));
}

SweepWindow SegSlam3d::window_after(std::size_t sweep) const {
  const Pose3 start_inverse = Pose4::level_of(sweeps_[sweep].odometry).level_pose3().inverse();
  Points3 all;
  for (std::size_t j = sweep;
       j < sweeps_.size() && sweeps_[j].time - sweeps_[sweep].time <= options_.segslam.segmentation.lookahead_s; ++j) {
    const Pose3 to_start = start_inverse * sweeps_[j].odometry;
    for (const Ray3& r : sweeps_[j].rays) {
      if (r.hit && (r.end - r.origin).norm() <= options_.filter.insert.max_range) all.push_back(to_start * r.end);
    }
  }
  // The structure points only when a particle matches (window_with_structure).
  return make_sweep_window(all, static_cast<std::size_t>(options_.extras.window_points), options_.segslam.matching,
                           false);
}

SegSlam3d::Transition SegSlam3d::ask_submap(SegParticle3& p, const SweepWindow& w, std::mt19937_64& rng) {
  Transition t;
  const SegmentationOptions& so = options_.segslam.segmentation;
  const MatchingOptions& mo = options_.segslam.matching;
  // SegSLAM eq. (17) only where it can decide (a large enough submap, motion error below its bound).
  const bool score_it =
      p.submap_updates >= so.min_segment_updates && p.motion_error < so.max_motion_error && so.predictive_threshold > 0;
  const double score = score_it ? predictive_score(p.submap.map, p.pose, w) : -1.0;
  t.segment = should_segment(p.submap_updates, p.motion_error, score, so);
  const bool periodic = p.updates_since_match >= mo.period_updates && p.submap_updates >= mo.period_updates;
  if (t.segment || periodic) {
    ask_matches(p, w, t, rng);
    p.updates_since_match = 0;
  }
  return t;
}

void SegSlam3d::choose_submap(SegParticle3& p, Transition& t, const SweepWindow& w, std::mt19937_64& rng) {
  const MatchingOptions& mo = options_.segslam.matching;
  collect_matches(p, w, t);
  const std::vector<std::size_t>& ids = t.ids;
  const std::vector<WindowMatch3>& matches = t.matches;
  const bool segment = t.segment;
  std::vector<double> weights;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    weights.push_back(matches[i].weight);
    t.offers.push_back(offer_of(ids[i], t.guesses[i], matches[i]));
  }
  const ChoiceDraw draw = draw_submap_choice(segment, weights, mo, rng);  // SegSLAM eq. (3)
  if (draw.choice == SubmapChoice::kMatch) t.offers[draw.match].chosen = true;
  if (draw.choice == SubmapChoice::kSame) return;
  // A pending wide re-entry (wide_reentry.hpp) follows the particle into a fresh frame, which
  // starts at its pose; a match moves it into another candidate's frame, and it is dropped.
  if (p.pending)
    p.pending = draw.choice == SubmapChoice::kNew ? std::optional(carried_into(*p.pending, p.pose)) : std::nullopt;
  if (t.wide && draw.choice == SubmapChoice::kNew) t.wide->carried = p.pose;
  if (t.wide && draw.choice == SubmapChoice::kMatch) t.wide->dropped = true;
  const RangeSweep& at = sweeps_[last_update_];
  OctreeSubmap next;
  next.interval = {last_update_, last_update_, at.time, at.time};
  if (draw.choice == SubmapChoice::kNew) {
    next.map = EvidenceOctree(options_.filter.map);  // a fresh level frame at the robot
    const Euler e = euler_of(at.odometry.linear());
    insert_rays(next.map, rays_at(Pose4{}.with_tilt(e.roll, e.pitch), at.rays), options_.filter.insert);
  } else {
    t.candidate = ids[draw.match];
    next.entry = matches[draw.match].pose;
    next.parent = t.candidate;
    next.map = segmap_.at(t.candidate).map;  // copy-on-write: shares every brick until written
    next.locked = locks_on_entry(matches[draw.match].icp_error, t.candidate);
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
}

void SegSlam3d::advance(SegParticle3& p, const SweepModel& s, std::mt19937_64& rng) const {
  // The 3D RBPF's particle step: motion-model proposal, end-point likelihood, ray insertion.
  const Pose3 before = p.pose.with_tilt(s.imu_before.roll, s.imu_before.pitch);
  const Pose3 after = sample_motion3(before, s.increment, s.imu, s.yaw_change, options_.filter.motion, rng);
  p.pose = Pose4::level_of(after);
  std::vector<Eigen::Vector3d> world(s.ends.size());
  for (std::size_t k = 0; k < s.ends.size(); ++k) world[k] = after * s.ends[k];
  p.log_weight +=
      options_.filter.weight_exponent * octree_log_likelihood(p.submap.map, world, options_.filter.likelihood);
  // A locked submap is localised in, never written (SegSLAM sec. 6): the particle keeps sharing the
  // matched submap's octree, and skips the ray insertion that dominates the 3D step.
  if (!p.submap.locked) insert_rays(p.submap.map, rays_at(after, s.rays), options_.filter.insert);
  p.submap.path.push_back({s.sweep, p.pose});
  p.submap.interval.last_scan = s.sweep;
  p.submap.interval.t_end = sweeps_[s.sweep].time;
  p.submap.exit = p.pose;
  ++p.submap_updates;
  ++p.updates_since_match;
  p.motion_error += s.motion_error;
}

void SegSlam3d::update(std::size_t k) {
  const RangeSweep& prev = sweeps_[last_update_];
  const RangeSweep& now = sweeps_[k];
  SweepModel s;
  s.sweep = k;
  s.increment = prev.odometry.inverse() * now.odometry;
  s.imu_before = euler_of(prev.odometry.linear());
  s.imu = euler_of(now.odometry.linear());
  s.yaw_change = normalize_angle(s.imu.yaw - s.imu_before.yaw);
  s.motion_error = motion_error_increment(
      Pose4::level_of(prev.odometry).between(Pose4::level_of(now.odometry)).planar(), options_.segslam.segmentation);
  const auto step = static_cast<std::size_t>(options_.filter.likelihood_ray_step);
  for (std::size_t i = 0, hits = 0; i < now.rays.size(); ++i) {
    if (now.rays[i].hit && hits++ % step == 0) s.ends.push_back(now.rays[i].end);
  }
  for (std::size_t i = 0; i < now.rays.size(); i += static_cast<std::size_t>(options_.filter.insert_ray_step)) {
    s.rays.push_back(now.rays[i]);
  }
  motion_error_sum_.resize(k + 1, 0.0);
  motion_error_sum_[k] = motion_error_sum_[last_update_] + s.motion_error;
  const SweepWindow w = window_after(last_update_);
  match_cache_.clear();
  matched_window_.reset();
  const int n = static_cast<int>(particles_.size());
  std::vector<Transition> transitions(particles_.size());
  std::vector<double> gain(particles_.size(), 0.0);
  std::vector<char> warm(particles_.size(), 0);
  std::vector<std::mt19937_64> rngs(particles_.size());
  const auto step_particle = [&](std::size_t u) {
    const double before = particles_[u].log_weight;
    advance(particles_[u], s, rngs[u]);
    gain[u] = particles_[u].log_weight - before;
  };
  // Prediction (SegSLAM eq. (3)) in three steps: each particle asks for its matches, the capped searches
  // run for all of them together (seg_slam3d_capped.cpp), each particle draws its submap and
  // steps; the wide searches asked for run last, beside the steps of the particles that asked.
  ParallelErrors asked;
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count())
  for (int i = 0; i < n; ++i) {
    asked.run([&] {
      const auto u = static_cast<std::size_t>(i);
      rngs[u].seed(mix_seed(options_.filter.seed, stats_.updates, static_cast<std::uint64_t>(i)));
      transitions[u] = ask_submap(particles_[u], w, rngs[u]);
    });
  }
  asked.rethrow();
  run_capped_stage(transitions, w);
  ParallelErrors stepped;
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count())
  for (int i = 0; i < n; ++i) {
    stepped.run([&] {
      const auto u = static_cast<std::size_t>(i);
      SegParticle3& p = particles_[u];
      choose_submap(p, transitions[u], w, rngs[u]);
      warm[u] = p.submap_updates >= options_.extras.warmup_updates || p.submap.parent != kNoSubmap;
      if (!transitions[u].wide) step_particle(u);
    });
  }
  stepped.rethrow();
  run_wide_stage(transitions, w, step_particle);
  // Deviation (as in 2D): a fresh submap has little to weigh its first sweeps against; it
  // gets the mean factor of the other particles, so starting a submap is neither rewarded
  // nor punished.
  double sum = 0;
  int warm_count = 0;
  for (std::size_t i = 0; i < gain.size(); ++i)
    if (warm[i]) sum += gain[i], ++warm_count;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    if (!warm[i] && warm_count > 0) particles_[i].log_weight += sum / warm_count - gain[i];
  }
  for (const SegParticle3& p : particles_) stats_.locked_updates += p.submap.locked ? 1 : 0;
  store_transitions(transitions);
  last_update_ = k;
  ++stats_.updates;
  // SegSLAM eq. (6)-(7): the RBPF's selective resampling (Grisetti et al. 2007, sec. IV step 5).
  shift_log_weights(particles_);
  bool resampled = false;
  stats_.neff.push_back(resample_if_degenerate(particles_, options_.filter.resample_threshold, rng_, resampled));
  if (resampled) ++stats_.resamplings;
  if (stats_.updates % 10 == 0) prune();
}

void SegSlam3d::run_wide_stage(std::vector<Transition>& transitions, const SweepWindow& w,
                               const std::function<void(std::size_t)>& step_particle) {
  // The wide searches asked for, one per segment (seg_slam3d_wide.cpp), beside the steps of
  // the particles that asked (a step does not need its particle's search: the re-entry it
  // finds waits for the next attempt).
  std::vector<const WideRequest*> requests(transitions.size(), nullptr);
  std::vector<std::size_t> waiting;
  for (std::size_t u = 0; u < transitions.size(); ++u) {
    if (transitions[u].wide) requests[u] = &*transitions[u].wide, waiting.push_back(u);
  }
  std::vector<WideSearch> searches = wide_searches(requests);
  // As tasks: a search hands its ICP refinements out as tasks too (wide_reentry.cpp), so the
  // thread done with the steps helps with the one search there usually is.
  ParallelErrors errors;
#pragma omp parallel num_threads(thread_count()) if (!waiting.empty())
#pragma omp single
  {
    for (WideSearch& search : searches) {
#pragma omp task default(shared)
      errors.run([&] { run_wide_search(search, w); });
    }
    for (const std::size_t u : waiting) {
#pragma omp task default(shared) firstprivate(u)
      errors.run([&] { step_particle(u); });
    }
  }
  errors.rethrow();
  for (WideSearch& search : searches) {
    for (std::size_t m = 0; m < search.members.size(); ++m) {
      Transition& t = transitions[search.members[m]];
      apply_wide(particles_[search.members[m]], *t.wide, search.results[m], t.attempts);
    }
  }
}

void SegSlam3d::store_transitions(std::vector<Transition>& transitions) {
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    Transition& t = transitions[i];
    for (MatchAttempt3& a : t.attempts) {
      a.particle = i;
      stats_.attempts.push_back(std::move(a));
    }
    for (const MatchEvent3& e : t.offers) {
      stats_.match_offers.push_back(e);
      if (e.chosen) stats_.match_events.push_back(e);
    }
    if (!t.closed_one) continue;
    const std::size_t id = segmap_.add(std::move(t.closed));
    particles_[i].submap.predecessor = id;
    if (t.candidate == kNoSubmap) {
      ++stats_.segmentations;
    } else {
      ++stats_.matches;
      stats_.locked += particles_[i].submap.locked ? 1 : 0;
    }
    merge_if_registered(id, t.closed_entry_error);
  }
}

void SegSlam3d::prune() {
  std::vector<std::size_t> roots;
  for (const SegParticle3& p : particles_) roots.push_back(p.submap.predecessor), roots.push_back(p.submap.parent);
  stats_.pruned += segmap_.prune(roots);
  for (auto it = targets_.begin(); it != targets_.end();)
    it = segmap_.contains(it->first) ? std::next(it) : targets_.erase(it);
}

std::size_t SegSlam3d::best_particle() const { return best_particle_index(particles_); }

std::vector<std::pair<std::size_t, Pose4>> SegSlam3d::trajectory(std::size_t m) const {
  const auto chain = temporal_chain(segmap_, particles_.at(m).submap);
  return reconstruct_trajectory(chain, chain_frames_with_matches(segmap_, chain));
}

std::vector<Pose4> SegSlam3d::trajectory_at_every_sweep(std::size_t m) const {
  return poses_at_every_scan(trajectory(m), sweeps_.size(), [&](std::size_t from, std::size_t to) {
    return Pose4::level_of(sweeps_[from].odometry).between(Pose4::level_of(sweeps_[to].odometry));
  });
}

SegmentedPath SegSlam3d::segmented_trajectory(std::size_t m) const {
  const auto chain = temporal_chain(segmap_, particles_.at(m).submap);
  const auto frames = chain_frames_with_matches(segmap_, chain);
  SegmentedPath out;
  for (std::size_t i = 0; i < chain.size(); ++i) {
    std::vector<Pose2> piece;
    for (const auto& [sweep, pose] : chain[i]->path) piece.push_back(frames[i].compose(pose).planar());
    out.pieces.push_back(std::move(piece));
    if (chain[i]->parent != kNoSubmap) {
      const Pose4 at = frames[i].compose(chain[i]->entry);
      out.matches.emplace_back(at.x, at.y);
    }
  }
  return out;
}

Pose4 SegSlam3d::global_pose(std::size_t m) const {
  const auto chain = temporal_chain(segmap_, particles_.at(m).submap);
  return chain_frames_with_matches(segmap_, chain).back().compose(particles_[m].pose);
}

Pose4 SegSlam3d::estimate() const {
  const Pose4 mean =
      weighted_mean_level_pose(particle_weights(particles_), [&](std::size_t m) { return global_pose(m); });
  return mean.compose(
      Pose4::level_of(sweeps_[last_update_].odometry).between(Pose4::level_of(sweeps_.back().odometry)));
}

}  // namespace lookahead::slam::segslam
