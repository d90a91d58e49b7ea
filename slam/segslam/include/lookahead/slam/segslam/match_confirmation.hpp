// SPDX-License-Identifier: MIT
// Confirmed re-entries for SegSLAM 2D: a match (sec. 4.5) that the particle's previous
// matching attempt predicted weighs more in eq. 3. The previous attempt's match of the same
// segment, carried along the particle's own motion since, predicts the window's pose in the
// candidate's frame; this attempt's ICP pose near it is a second, independent window saying
// the same thing.
//
// Deviation (not in the paper, whose eq. 18 weighs every match by its own window alone): on
// MIT CSAIL's raw log right and wrong re-entries have the same ICP errors (0.117 against
// 0.133 m mean; bench/segslam/csail_match_labels.py), so eq. 18 weighs an alias about half a
// right match, both far below the null match, and most right re-entries are not taken. An
// alias rarely lands where the previous window's match predicts. Holding back every match
// until it is confirmed (the 3D wide stage's rule, wide_reentry.hpp) lost more loops than it
// saved (README, "Loop closure on MIT CSAIL"): a confirmed match is favoured instead, by
// MatchingOptions::confirmed_boost (off by default: it helped 5 particles, not 40).
#pragma once

#include <cstddef>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::segslam {

/// A match of the last attempt: the particle's open submap frame in the frame of `segment`'s
/// candidate (pose in the candidate's frame = frame.compose(pose in the submap's)).
struct PendingMatch {
  std::size_t segment = 0;  ///< SegMap::first_copy of the candidate
  Pose2 frame;
};

/// The pending match of a particle at `pose` in its submap, matched at `match` in `segment`.
PendingMatch pending_match(std::size_t segment, const Pose2& match, const Pose2& pose);

/// The same match after the particle started a fresh submap whose frame is `origin` in the
/// old one.
PendingMatch carried_into(const PendingMatch& pending, const Pose2& origin);

/// Does a match of `segment` at `match`, the particle at `pose` in its submap, confirm one of
/// `pending`: the same segment, and `match` within `distance` [m] and `angle` [rad] of where
/// that pending match puts the particle now?
bool confirms(const std::vector<PendingMatch>& pending, std::size_t segment, const Pose2& match, const Pose2& pose,
              double distance, double angle);

}  // namespace lookahead::slam::segslam
