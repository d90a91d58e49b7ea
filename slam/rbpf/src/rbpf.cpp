// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/rbpf.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "lookahead/slam/limits/input_limits.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/rbpf/improved_proposal.hpp"
#include "lookahead/slam/rbpf/interpolated_trajectory.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "lookahead/slam/rbpf/particle_step.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::slam {
namespace {

void validate(const RbpfOptions& o) {
  if (o.particles < 1 || o.particles > 100000) throw std::invalid_argument("particles in 1..100000");
  if (!(o.resample_threshold > 0 && o.resample_threshold <= 1)) {
    throw std::invalid_argument("resample_threshold in (0, 1]");
  }
  if (o.linear_update < 0 || o.angular_update < 0) throw std::invalid_argument("update thresholds >= 0");
  if (o.threads < 0) throw std::invalid_argument("threads >= 0");
  if (!(o.weight_exponent > 0 && o.weight_exponent <= 1)) {
    throw std::invalid_argument("weight_exponent in (0, 1]");
  }
  if (!(o.matcher.min_hit_ratio >= 0 && o.matcher.min_hit_ratio <= 1)) {
    throw std::invalid_argument("matcher.min_hit_ratio in [0, 1] (proposal.kind: motion_model skips the matcher)");
  }
  const PredictionOptions& pr = o.prediction;
  if (!(pr.hit_ratio_threshold >= 0 && pr.hit_ratio_threshold <= 1)) {
    throw std::invalid_argument("prediction.hit_ratio_threshold in [0, 1]");
  }
  if (pr.min_predicted_beams < 1 || pr.max_hypotheses < 1) {
    throw std::invalid_argument("prediction.min_predicted_beams and max_hypotheses >= 1");
  }
}

// Every particle writes its own copy of each tile a scan touches (copy-on-write), so after
// the first update the particles hold about N times the tiles the first scan wrote.
void check_particle_memory(const OccupancyGrid& first_map, int particles) {
  const auto tiles = static_cast<double>(first_map.tile_count());
  limits::check_memory(
      particles * tiles * sizeof(GridTile),
      fmt::format("{} particles x {} map tiles of {} bytes", particles, first_map.tile_count(), sizeof(GridTile)));
}

}  // namespace

Rbpf::Rbpf(const RbpfOptions& options)
    : options_((validate(options), options)),
      motion_(options.motion),
      prototype_grid_(options.grid),
      likelihood_(options.likelihood, prototype_grid_),
      matcher_(options.matcher, likelihood_),
      rng_(mix_seed(options.seed, 0xABCDEFull, 0)) {}

bool Rbpf::add_scan(const LaserScan& scan) {
  timestamps_.push_back(scan.timestamp);
  odometry_.push_back(scan.odometry);
  ++stats_.scans;
  if (particles_.empty()) {
    initialize(scan);
    return true;
  }
  if (!motion_threshold_met(scan)) {
    track_between_updates(scan);
    return false;
  }
  since_update_.push_back(Pose2{});
  since_estimate_.push_back(Pose2{});
  tracked_.push_back(false);
  update_particles(scan);  // Grisetti et al. sec. IV steps 1-4: proposal, weights, map
  resample_if_needed();    // step 5: selective resampling
  last_update_odometry_ = scan.odometry;
  return true;
}

void Rbpf::initialize(const LaserScan& scan) {
  // The map frame is the odometry frame at the first scan, so maps and odometry overlay.
  Particle p{scan.odometry, prototype_grid_, 0.0, nullptr, {}};
  insert_scan(p.map, p.pose, scan, options_.insert);
  check_particle_memory(p.map, options_.particles);
  p.trajectory = std::make_shared<TrajectoryNode>(p.pose, 0, nullptr);
  particles_.assign(static_cast<std::size_t>(options_.particles), p);
  since_update_.assign(1, Pose2{});
  since_estimate_.assign(1, Pose2{});
  tracked_.assign(1, false);
  last_update_odometry_ = scan.odometry;
  stats_.updates = 1;
  stats_.neff.push_back(static_cast<double>(options_.particles));
}

// A scan between updates is matched on the best particle's map (weights, and so the best
// particle, change only at updates): its pose relative to the last update, for the trajectory
// and the pose a robot in the loop plans from. The map is not changed.
void Rbpf::track_between_updates(const LaserScan& scan) {
  const Particle& best = particles_[best_particle()];
  const std::size_t n = odometry_.size();
  const Pose2 odometry_step = odometry_[n - 2].between(odometry_[n - 1]);
  const Pose2 guess = best.pose.compose(since_update_.back().compose(odometry_step));
  const std::optional<Pose2> tracked = track_on(best, guess, scan);
  since_update_.push_back(best.pose.between(tracked.value_or(guess)));
  // The trajectory's node holds the proposal's mean, not the pose drawn for the map: a
  // tracked scan is placed relative to that mean, or the draw's noise would come back at
  // every scan between updates as heading wobble.
  const Pose2& node = best.trajectory->pose;
  since_estimate_.push_back(tracked ? node.between(*tracked) : since_estimate_.back().compose(odometry_step));
  tracked_.push_back(tracked.has_value());
}

// The scan's pose on `p`'s map: the mean of the improved proposal (Grisetti et al. 2007,
// eq. (12)) around the match, the estimate the trajectory keeps at updates too; none before
// the warm-up ends, with the motion-model proposal, or where the match fails. One particle
// is tracked, so it can afford the bilinear field: sub-cell heading between updates. The
// particles' own proposals keep the cell lookup; with the bilinear field there too the
// trajectory drifts (docs/algorithms/rbpf.md).
std::optional<Pose2> Rbpf::track_on(const Particle& p, const Pose2& guess, const LaserScan& scan) const {
  const bool warm = stats_.updates > static_cast<std::size_t>(options_.warmup_updates);
  if (!warm || options_.proposal.kind != ProposalKind::kScanMatch) return std::nullopt;
  const PreparedScan prepared = prepare_scan(scan, options_.likelihood);
  const MatchResult m = matcher_.match(p.map, guess, prepared, 0.0, FieldLookup::kBilinear);
  if (!m.ok) return std::nullopt;
  const Pose2 u = last_update_odometry_.between(scan.odometry);
  return improved_proposal(p.map, p.pose, u, m.pose, prepared, likelihood_, motion_, options_.proposal,
                           FieldLookup::kBilinear)
      .mean;
}

bool Rbpf::motion_threshold_met(const LaserScan& scan) const {
  const Pose2 moved = last_update_odometry_.between(scan.odometry);
  return moved.norm() >= options_.linear_update || std::abs(moved.theta) >= options_.angular_update;
}

void Rbpf::update_particle(Particle& p, const Pose2& u, const LaserScan& scan, const PreparedScan& prepared,
                           std::mt19937_64& rng, bool& failed, HypothesisScore& on_hypotheses) const {
  const bool warm = stats_.updates > static_cast<std::size_t>(options_.warmup_updates);
  const ParticleStepModels models{options_, motion_, likelihood_, matcher_};
  // The map takes the pose drawn from N(mu, Sigma) (Grisetti et al. 2007, sec. III-B); the
  // trajectory keeps mu (eq. 12): the same hypothesis without the draw's noise, which would
  // otherwise show as heading wobble between updates.
  Pose2 estimate = p.pose;
  failed = draw_particle(models, p.map, p.pose, p.log_weight, u, prepared, warm, rng, &estimate);
  // S2 reads the map before this scan (m_{k-1}): after insertion every end point is explored.
  if (warm && !hypotheses_.empty()) {
    on_hypotheses = score_on_hypotheses(p.map, p.pose, prepared, hypotheses_, p.hypothesis_offsets, likelihood_);
  }
  insert_scan(p.map, p.pose, scan, options_.insert);
  p.trajectory = std::make_shared<TrajectoryNode>(estimate, timestamps_.size() - 1, p.trajectory);
}

void Rbpf::update_particles(const LaserScan& scan) {
  const Pose2 u = last_update_odometry_.between(scan.odometry);
  const PreparedScan prepared = prepare_scan(scan, options_.likelihood);
  const int n = static_cast<int>(particles_.size());
  const int threads = options_.threads > 0 ? options_.threads : omp_get_num_procs();
  std::vector<char> failed(particles_.size(), 0);
  std::vector<HypothesisScore> predicted(particles_.size());
  ParallelErrors errors;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    errors.run([&] {
      const auto k = static_cast<std::size_t>(i);
      std::mt19937_64 rng(mix_seed(options_.seed, stats_.updates, static_cast<std::uint64_t>(i)));
      bool f = false;
      update_particle(particles_[k], u, scan, prepared, rng, f, predicted[k]);
      failed[k] = f ? 1 : 0;
    });
  }
  errors.rethrow();
  if (!hypotheses_.empty()) apply_hypothesis_weights(predicted);
  stats_.match_failures += static_cast<std::size_t>(std::count(failed.begin(), failed.end(), 1));
  stats_.particle_updates += particles_.size();
  ++stats_.updates;
}

// P-SLAM eq. (21)-(22): w = w S1(z_e | m) S2(z_u | h). S1 is already in the weight: the improved
// proposal's eta scores every end point on m, and end points in unexplored cells score the
// same constant there. Deviation: the paper assumes the motion-model proposal; we keep the
// improved proposal (scan matching on m only) and multiply S2 at the drawn pose, tempered
// with the same exponent k as eta.
void Rbpf::apply_hypothesis_weights(const std::vector<HypothesisScore>& scores) {
  const auto& o = options_.prediction;
  bool any_predicted = false, any_hit = false;
  for (const HypothesisScore& s : scores) {
    if (s.predicted_beams < o.min_predicted_beams) continue;
    any_predicted = true;
    any_hit = any_hit || s.hit_ratio() >= o.hit_ratio_threshold;
  }
  if (!any_predicted) return;
  ++stats_.predicted_updates;
  if (!any_hit) {  // P-SLAM eq. (23): no particle sees the prediction; it must be wrong here
    ++stats_.prediction_rejected;
    return;
  }
  ++stats_.prediction_used;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    // A particle below min_predicted_beams sees (almost) no predicted cells: its S2 over
    // the few it sees is still its evidence, so every particle gets its own S2.
    particles_[i].log_weight += options_.weight_exponent * scores[i].log_likelihood;
  }
}

void Rbpf::add_hypothesis(std::shared_ptr<const HypothesisMap> hypothesis) {
  if (!options_.prediction.enabled || !hypothesis || particles_.empty()) return;
  const Pose2 best = particles_[best_particle()].pose;
  const auto max = static_cast<std::size_t>(std::max(1, options_.prediction.max_hypotheses));
  const bool drop_oldest = hypotheses_.size() >= max;
  if (drop_oldest) hypotheses_.erase(hypotheses_.begin());
  hypotheses_.push_back(std::move(hypothesis));
  for (Particle& p : particles_) {
    if (drop_oldest) p.hypothesis_offsets.erase(p.hypothesis_offsets.begin());
    // offset (+) x_n = x_best: a point seen from particle n lands where the best sees it.
    p.hypothesis_offsets.push_back(best.compose(p.pose.inverse()));
  }
  ++stats_.hypotheses_added;
}

void Rbpf::clear_hypotheses() {
  hypotheses_.clear();
  for (Particle& p : particles_) p.hypothesis_offsets.clear();
}

// Grisetti et al. 2007, sec. IV step 5: N_eff (eq. (20)) decides whether the set is redrawn.
void Rbpf::resample_if_needed() {
  shift_log_weights(particles_);
  bool resampled = false;
  stats_.neff.push_back(resample_if_degenerate(particles_, options_.resample_threshold, rng_, resampled));
  if (resampled) ++stats_.resamplings;
}

std::size_t Rbpf::best_particle() const { return best_particle_index(particles_); }

Pose2 Rbpf::current_pose() const {
  if (particles_.empty()) return {};
  return particles_[best_particle()].pose.compose(since_update_.back());
}

Pose2 Rbpf::mean_pose() const {
  if (particles_.empty()) return {};
  const Pose2 mean =
      weighted_mean_pose(particle_weights(particles_), [&](std::size_t m) { return particles_[m].pose; });
  return mean.compose(since_update_.back());
}

std::vector<Pose2> Rbpf::best_trajectory() const {
  if (particles_.empty()) return std::vector<Pose2>(timestamps_.size());
  std::vector<std::pair<std::size_t, Pose2>> updates;
  for (const TrajectoryNode* n : chain_oldest_first(particles_[best_particle()].trajectory.get())) {
    updates.emplace_back(n->scan_index, n->pose);
  }
  // A radian of turn weighs as much as the update thresholds make it (0.5 m / 0.25 rad: 2 m).
  const double metres_per_radian = options_.angular_update > 0 ? options_.linear_update / options_.angular_update : 0.0;
  return interpolate_between_updates(
      updates, odometry_, [&](std::size_t, std::size_t s) { return since_estimate_[s]; },
      [&](std::size_t s) { return tracked_[s]; }, metres_per_radian);
}

}  // namespace lookahead::slam
