// SPDX-License-Identifier: MIT
// The wide re-entry search of SegSLAM 3D: a second matching stage for a candidate whose
// position in the map sample is more uncertain than the capped search covers, accepted only
// when it is unambiguous (Fairfield et al. 2010, SegSLAM sec. 4.5.2, eq. 19).
//
// Why: at the garage loop's end a few-particle filter's map sample may place the start area
// tens of metres and most of a radian off, beyond the capped +-6 m / 0.4 rad search of
// candidate_reach.hpp, so the loop stays open. A blindly wider search finds wrong re-entries:
// the garage repeats its columns about 9 m apart, and a shift by one spacing fits the
// structure test as well as the right pose.
//
// What the paper does: SegSLAM sec. 4.5.2 sizes its localisation filter's initial spread by the
// uncertainty the map sample accumulates ("candidate positions at the end of long loops will
// be uncertain"), and SegSLAM eq. (19) weighs the match by p(|Sigma_X|), the determinant of the filter's
// final covariance: a filter left spread over two places weighs little. Deviation, as the
// localisation filter is not in 3D: the search region is sized by SegSLAM eq. (18)'s sigma_tau =
// hypot(translation_sigma, e), e the SegSLAM eq. (13)-(14) error along the map sample's links that placed
// the candidate (SegSlam3d::chain_errors), `sigmas` of them (where p(tau^2) leaves weight),
// and a yaw reach grown with the same error; the stage runs only where `trigger_sigmas` of
// them exceed the capped search, and there only after it found nothing;
// the coarse search's distinct peaks in that region are each refined by ICP and tested, and
// the match stands only when exactly one distinct pose passes. Two passing poses are the two
// modes SegSLAM eq. (19)'s covariance would see: the match is rejected ("ambiguous") rather than drawn.
// An unambiguous wide match is not offered at once either: it is kept as the particle's
// pending re-entry and offered (SegSLAM eq. (3), weighted by SegSLAM eq. (18)) only when the next matching
// attempt, a window later, finds the window's pose by ICP where that re-entry predicts it.
// On the garage a wrong re-entry one column spacing off can pass the tests for one window
// and fails the next. A confirmed re-entry stays pending and is offered again at every
// attempt whose window confirms it: its SegSLAM eq. (18) weight is low where the guess is far
// (tau well above sigma_tau), so one offer is rarely taken.
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
  /// The reach is this many of SegSLAM eq. (18)'s sigma_tau = hypot(translation_sigma, e). > 0
  /// (a single particle's guesses come within about 2.6 e).
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
  /// Yaw reach hypot(search_angle, angle_per_error e) [rad per m of SegSLAM eq. (13)-(14) error], capped
  /// at max_angle [rad]. The SegSLAM eq. (13)-(14) error is a position error; the heading error that a
  /// gyro bias leaves is not in it, and at a loop's end (near its start) a heading error moves
  /// the guess little, so the yaw reach has its own rate (a single particle's guesses come
  /// within about 0.09 rad per m of that error).
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
};

/// An unambiguous wide match waiting for the next attempt's confirmation: the frames of the
/// particle's open submap in the candidate's frame, as the match and as the map sample placed
/// it (pose in the candidate's frame = frame.compose(pose in the submap's)).
struct PendingReentry {
  std::size_t candidate = 0;
  Pose4 frame;        ///< by the match
  Pose4 guess_frame;  ///< by the map sample, for SegSLAM eq. (18)'s tau
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

/// The wide stage's options for a candidate left `error_since` [m] of SegSLAM eq. (13)-(14) error ago, or
/// nothing when trigger_sigmas sigma_tau do not exceed `narrow_cap` (the capped search of
/// candidate_reach covers most of p(tau^2)) or the stage is off. SegSLAM eq. (18)'s sigma_tau is candidate_reach's; the
/// proximity radius grows by as much as the search's reach.
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
/// match_window_unambiguous's answer among them (tau and the SegSLAM eq. (18) weight taken from the
/// region's centre with `options`' sigma). With one region it is match_window_unambiguous
/// bit for bit. (The peaks of the covering square alone would not do: its best four may all
/// lie outside a region, which then sees one alias and no right pose to make it ambiguous.)
/// Why: the copies of one segment ask for several wide searches per update from guesses a
/// few metres apart, each as costly as one over all of them.
std::vector<WindowMatch3> match_regions_unambiguous(const OctreeMatchTarget& target, const SweepWindow& window,
                                                    const std::vector<WideRegion>& regions,
                                                    const MatchingOptions& options,
                                                    const StructureTestOptions& structure,
                                                    const WideReentryOptions& wide);

}  // namespace lookahead::slam::segslam
