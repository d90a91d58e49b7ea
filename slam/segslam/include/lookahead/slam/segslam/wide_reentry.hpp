// SPDX-License-Identifier: MIT
// The wide re-entry search of SegSLAM 3D: a second matching stage for a candidate whose
// position in the map sample is more uncertain than the capped search covers, accepted only
// when it is unambiguous (Fairfield et al. 2010, sec. 4.5.2, eq. 19).
//
// Why: at the garage loop's end a single particle's map sample places the start area 8-26 m
// and 0.2-0.8 rad off the truth (1 particle, seeds 1, 4, 6, 7, 8; README), beyond the capped
// +-6 m / 0.4 rad search of candidate_reach.hpp, so the loop stays open. A blindly wider
// search finds wrong re-entries: the garage repeats its columns about 9 m apart, and a shift
// by one spacing fits the structure test as well as the right pose (seed 4, sweep 229).
//
// What the paper does: sec. 4.5.2 sizes its localisation filter's initial spread by the
// uncertainty the map sample accumulates ("candidate positions at the end of long loops will
// be uncertain"), and eq. 19 weighs the match by p(|Sigma_X|), the determinant of the filter's
// final covariance: a filter left spread over two places weighs little. Deviation, as the
// localisation filter is not in 3D: the search region is sized by eq. 18's sigma_tau =
// hypot(translation_sigma, e), e the eq. 13-14 error along the map sample's links that placed
// the candidate (SegSlam3d::chain_errors), `sigmas` of them (where p(tau^2) leaves weight),
// and a yaw reach grown with the same error; the stage runs only where `trigger_sigmas` of
// them exceed the capped search, and there only after it found nothing;
// the coarse search's distinct peaks in that region are each refined by ICP and tested, and
// the match stands only when exactly one distinct pose passes. Two passing poses are the two
// modes eq. 19's covariance would see: the match is rejected ("ambiguous") rather than drawn.
// An unambiguous wide match is not offered at once either: it is kept as the particle's
// pending re-entry and offered (eq. 3, weighted by eq. 18) only when the next matching
// attempt, a window later, finds the window's pose by ICP where that re-entry predicts it.
// On the garage a wrong re-entry one column spacing off passes the tests for one window (seed
// 1, 1 particle, sweep 229: 12 m off, eq. 18 weight above the null match's) and fails the next.
// A confirmed re-entry stays pending and is offered again at every attempt whose window
// confirms it: its eq. 18 weight is low where the guess is far (tau 10-19 m against sigma_tau
// 8 m: 0.03-0.06 against the null match's 0.28), so one offer is rarely taken.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "lookahead/slam/segslam/octree_submap_ops.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"

namespace lookahead::slam::segslam {

struct WideReentryOptions {
  /// Cap of the wide search's reach [m]; 0 turns the wide stage off.
  double max_radius = 25.0;
  /// The reach is this many of eq. 18's sigma_tau = hypot(translation_sigma, e). > 0. The
  /// single particle's guesses were up to 2.6 e off on the garage loop (--data-seed 1 and 2).
  double sigmas = 3.0;
  /// The stage runs only where this many sigma_tau exceed the capped search (it leaves a
  /// share of p(tau^2) out worth the cost). 0 < trigger_sigmas <= sigmas.
  double trigger_sigmas = 2.0;
  /// The wide search starts from the map sample's guess rounded to this grid [m], [rad], so
  /// that particles with nearby guesses share one search (the reach is metres); taken as the
  /// nearest whole number of the coarse search's steps (2.4 m with 0.3 m steps), so that the
  /// grids of particles searched together coincide (seg_slam3d_wide.cpp).
  double guess_step = 2.5;
  double guess_angle_step = 0.2;
  /// Yaw reach hypot(search_angle, angle_per_error e) [rad per m of eq. 13-14 error], capped
  /// at max_angle [rad]. The eq. 13-14 error is a position error; the heading error that a
  /// gyro bias leaves is not in it, and at a loop's end (near its start) a heading error moves
  /// the guess little, so the yaw reach has its own rate: the single particle's guesses at the
  /// capped search's code were at most 0.09 rad off per m of that error (--data-seed 1 and 2).
  double angle_per_error = 0.1;
  double max_angle = 1.0;
  /// Distinct coarse peaks refined by ICP and tested. >= 2.
  std::size_t peaks = 4;
  /// Poses farther apart than this in the plane [m] or in yaw [rad] are distinct.
  double separation = 1.5;
  double angle_separation = 0.15;
  /// A pending re-entry is confirmed when the next window's ICP pose is this near the
  /// predicted one [m], [rad].
  double confirm_distance = 0.5;
  double confirm_angle = 0.08;
  /// After a wide search of a candidate found nothing, the particle searches that candidate
  /// widely again only this many filter updates later; 0 at every attempt. >= 0.
  /// Deviation (not in the paper, whose localisation filter runs once per re-entry decision):
  /// on the garage loop the stage searched the same candidate at every attempt, 4 updates
  /// (about 4 m of travel) apart, most of them failing while the robot was still 4-20 m from
  /// the candidate's mapped area (1 particle, seed 1: 18 wide searches of one candidate, all
  /// failed); the region a search covers (3 sigma_tau, 12-25 m) moves little between attempts.
  int retry_updates = 0;
  /// The stage runs only in filters of at most this many particles; 0 (the default): at any count.
  /// Why an option (README "The wide stage only up to N particles: an option, not the default"):
  /// its trigger sizes the map sample's error by the eq. 13-14 model of dead reckoning, which does
  /// not see the particle count, while the filter's own drift shrinks with it (garage, 20
  /// particles, seed 1: 26 wide searches from guesses 0.4-2.5 m off where the model said 3-6 m,
  /// all in vain; without the stage 14 % less time at 20 particles, 8-9 % at 40 and 100). But the
  /// stage also repairs a capped-stage alias: with --data-seed 2, 20 particles, seed 8, six
  /// particles took the column-spacing alias 12 m off at sweep 234 and only a wide re-entry at
  /// sweep 300 brought the run back (0.32 m; 10.0 m without the stage). So it stays on.
  std::size_t max_particles = 0;
};

/// A particle's wide searches that found nothing, per candidate: the update from which that
/// candidate may be searched widely again (WideReentryOptions::retry_updates).
class WideBackoff {
 public:
  /// May `candidate` be searched widely at update `now`?
  [[nodiscard]] bool allows(std::size_t candidate, std::size_t now) const;
  /// A wide search of `candidate` at update `now` found nothing: wait `retry_updates` (the
  /// entries whose wait is over are dropped, so the list stays a few candidates long).
  void failed(std::size_t candidate, std::size_t now, int retry_updates);

 private:
  std::vector<std::pair<std::size_t, std::size_t>> until_;  ///< (candidate, first update allowed)
};

/// An unambiguous wide match waiting for the next attempt's confirmation: the frames of the
/// particle's open submap in the candidate's frame, as the match and as the map sample placed
/// it (pose in the candidate's frame = frame.compose(pose in the submap's)).
struct PendingReentry {
  std::size_t candidate = 0;
  Pose4 frame;        ///< by the match
  Pose4 guess_frame;  ///< by the map sample, for eq. 18's tau
};

/// The pending re-entry of a particle at `pose` in its submap that the wide stage matched to
/// `candidate` at `match` from the map sample's `guess`.
PendingReentry pending_of(std::size_t candidate, const Pose4& match, const Pose4& guess, const Pose4& pose);

/// The same re-entry after the particle started a fresh submap whose frame is `origin` in the
/// old one (a segmentation: the robot's pose then).
PendingReentry carried_into(const PendingReentry& pending, const Pose4& origin);

/// Does a window's ICP pose `found` confirm the pending re-entry's `predicted` one?
bool confirms(const Pose4& predicted, const Pose4& found, const WideReentryOptions& options);

/// Throws std::invalid_argument on impossible options.
void validate(const WideReentryOptions& options);

/// The wide stage's options for a candidate left `error_since` [m] of eq. 13-14 error ago, or
/// nothing when trigger_sigmas sigma_tau do not exceed `narrow_cap` (the capped search of
/// candidate_reach covers most of p(tau^2)) or the stage is off. Eq. 18's sigma_tau is candidate_reach's; the proximity
/// radius grows by as much as the search's reach.
std::optional<MatchingOptions> wide_reach(const MatchingOptions& base, double error_since, double narrow_cap,
                                          const WideReentryOptions& wide);

/// The wide search: up to `wide.peaks` distinct coarse peaks around `guess` within `options`'
/// reach, each refined by ICP and put to match_window's tests. The result is the one passing
/// pose when exactly one distinct pose passes; with two or more it is rejected as
/// "ambiguous"; with none it is the best peak's failed match. `modes` counts the passing ones
/// (2 when ambiguous: the peaks after the second passing pose are not refined).
WindowMatch3 match_window_unambiguous(const OctreeMatchTarget& target, const SweepWindow& window, const Pose4& guess,
                                      const MatchingOptions& options, const StructureTestOptions& structure,
                                      const WideReentryOptions& wide);

/// What one particle's wide search covers: +-radius [m] in x and y and +-angle [rad] in yaw
/// around `centre` (its guess, rounded).
using WideRegion = LevelSubgrid;

/// One wide search for several particles' regions of one candidate, on the grid of
/// covering_subgrid(regions): per region its own distinct coarse peaks (level_search_peaks_within:
/// the regions share the scores and bounds), each pose refined by ICP at most once, and
/// match_window_unambiguous's answer among them (tau and the eq. 18 weight taken from the
/// region's centre with `options`' sigma). With one region it is match_window_unambiguous
/// bit for bit. (The peaks of the covering square alone would not do: its best four may all
/// lie outside a region, which then sees one alias and no right pose to make it ambiguous;
/// 20 particles, seed 5: a match 12 m off taken at sweep 287.)
/// Why: at 20 particles the copies of one segment asked for 2-3 wide searches per update
/// from guesses a few metres apart (20 particles, seed 1: 84 searches at 32 updates, 82
/// distinct guess cells), each as costly as one over all of them.
std::vector<WindowMatch3> match_regions_unambiguous(const OctreeMatchTarget& target, const SweepWindow& window,
                                                    const std::vector<WideRegion>& regions,
                                                    const MatchingOptions& options,
                                                    const StructureTestOptions& structure,
                                                    const WideReentryOptions& wide);

}  // namespace lookahead::slam::segslam
