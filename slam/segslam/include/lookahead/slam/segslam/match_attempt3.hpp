// SPDX-License-Identifier: MIT
// One candidate a particle considered for a re-entry (SegSLAM sec. 4.5.1-4.5.2), with what became of
// it: winnowed by proximity, left out as not among the nearest, or matched (and why the match
// failed). Recorded only on request (SegSlam3dExtras::record_attempts), for the debug log
// that checks, against a simulator's ground truth, whether the right re-entry was in reach.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"

namespace lookahead::slam::segslam {

enum class AttemptOutcome {
  kFar,         ///< the guess is beyond the proximity radius of the candidate's path
  kUnobserved,  ///< near the path, but the candidate observed nothing around the guess
  kNotNearest,  ///< passed proximity, but more than max_candidates were nearer
  kRejected,    ///< matched, and the match failed its tests (`rejection`)
  kOffered,     ///< matched and offered to the particle (SegSLAM eq. (3))
  kPending,     ///< matched by the wide stage, to be confirmed at the next attempt
};

inline const char* name_of(AttemptOutcome o) {
  switch (o) {
    case AttemptOutcome::kFar:
      return "far";
    case AttemptOutcome::kUnobserved:
      return "unobserved";
    case AttemptOutcome::kNotNearest:
      return "not nearest";
    case AttemptOutcome::kRejected:
      return "rejected";
    case AttemptOutcome::kOffered:
      return "offered";
    case AttemptOutcome::kPending:
      return "pending";
  }
  return "?";
}

struct MatchAttempt3 {
  std::size_t sweep = 0;  ///< the update (the window's first sweep)
  std::size_t particle = 0;
  std::size_t candidate = 0;
  Pose4 guess;                    ///< the particle placed in the candidate's frame by the map sample
  double path_distance = 0.0;     ///< from the guess to the candidate's path, in the plane [m]
  double proximity_radius = 0.0;  ///< the radius it was held against [m]
  double search_radius = 0.0;     ///< the coarse search's reach used for it [m]
  double search_angle = 0.0;      ///< ... and in yaw [rad]
  double error_since = 0.0;       ///< SegSLAM eq. (13)-(14) error since the candidate was left [m]
  double chain_error = 0.0;       ///< ... and along the map sample's links to it (the wide stage's) [m]
  /// The wide stage's radius, reach and yaw reach (wide_reentry.hpp), 0 when it has none.
  double wide_proximity_radius = 0.0, wide_search_radius = 0.0, wide_search_angle = 0.0;
  bool wide = false;          ///< matched by the wide stage
  bool confirmation = false;  ///< the check of a pending re-entry (ICP from its prediction)
  std::size_t modes = 0;      ///< the wide stage's distinct passing poses
  /// The candidate's (or an ancestor's, same frame) path pose nearest to the guess: with
  /// ground truth, reference.between(guess) against the truth says how far off the guess is.
  std::size_t reference_sweep = 0;
  Pose4 reference;
  /// The sweeps the candidate and its ancestors cover (first, last): where the robot truly
  /// was when the candidate's map was made.
  std::vector<std::pair<std::size_t, std::size_t>> intervals;
  AttemptOutcome outcome = AttemptOutcome::kFar;
  double guess_score = 0.0, coarse_score = 0.0;  ///< WindowMatch3's, when matched
  Pose4 pose;                                    ///< the match's pose, when matched
  double match_path_distance = 0.0;              ///< from the match's pose to the candidate's path, in the plane [m]
  const char* rejection = "";                    ///< WindowMatch3's, when rejected
};

}  // namespace lookahead::slam::segslam
