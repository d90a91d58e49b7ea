// SPDX-License-Identifier: MIT
// SegSlam3d's per-particle state within one update (private to seg_slam3d*.cpp): what the
// particle asked to match (ask_submap), the capped searches' answers for it (run_capped_stage),
// and the submap it drew (choose_submap), stored into the SegMap after the update.
#pragma once

#include <optional>
#include <vector>

#include "lookahead/slam/segslam/seg_slam3d.hpp"

namespace lookahead::slam::segslam {

/// A submap of the particle's map sample left for matching (winnow).
struct SegSlam3d::Candidate {
  bool wide_only;  ///< beyond the capped reach, within the wide one (wide_reentry.hpp)
  std::optional<MatchingOptions> wide;
  double distance;
  std::size_t id;
  Pose4 guess;
  std::size_t attempt;  ///< index into the attempts when recording
};

struct SegSlam3d::Transition {
  // Asked (ask_submap).
  bool segment = false;  ///< eq. 13-14 / 17: the open submap ends at this update
  std::vector<Candidate> candidates;
  /// Per candidate: the capped search around its guess on the segment's first copy (or on
  /// the candidate itself, `share_by_segment` off), filled by run_capped_stage.
  std::vector<WindowMatch3> screens;
  // The matches offered (a confirmed pending re-entry first, then the candidates').
  std::vector<std::size_t> ids;
  std::vector<Pose4> guesses;
  std::vector<WindowMatch3> matches;
  double pending_weight = 0.0;  ///< eq. 18 weight of the pending re-entry confirmed now
  // Drawn (choose_submap).
  bool closed_one = false;
  OctreeSubmap closed;
  double closed_entry_error = 0.0;  ///< err_ICP of the match that opened `closed` (merging)
  std::size_t candidate = kNoSubmap;
  std::vector<MatchEvent3> offers;      ///< the matches offered; the one taken is `chosen`
  std::vector<MatchAttempt3> attempts;  ///< the candidates considered (record_attempts only)
  std::optional<WideRequest> wide;      ///< the wide search asked for, run after the predictions
};

}  // namespace lookahead::slam::segslam
