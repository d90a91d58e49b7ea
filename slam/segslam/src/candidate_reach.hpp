// SPDX-License-Identifier: MIT
// How far from the map sample's guess a re-entry into a candidate submap is looked for, given
// the SegSLAM eq. (13)-(14) motion error accumulated since the robot left that candidate
// (Fairfield et al. 2010, SegSLAM sec. 4.3.1, 4.5.2). SegSLAM sec. 4.5.2 spreads its localisation filter by that
// uncertainty ("candidate positions at the end of long loops will be uncertain"); the ICP
// matcher of SegSLAM eq. (18) has a fixed proximity radius and coarse search instead.
//
// Deviation: the proximity radius, the coarse search's reach and SegSLAM eq. (18)'s p(tau^2) all widen
// with that error e: sigma_tau = hypot(translation_sigma, e), reach = hypot(search_radius, e)
// capped at `max_search_radius` (the search's cost grows with the square of its reach), and
// the proximity radius by as much as the reach grew: at a long loop's end the map sample's
// guess may be several metres off, beyond a fixed +-2 m search.
#pragma once

#include "lookahead/slam/segslam/segslam_options.hpp"

namespace lookahead::slam::segslam {

/// The matching options for a candidate left `error_since` [m] of SegSLAM eq. (13)-(14) error ago.
/// `max_search_radius` >= 0 caps the coarse search (never below options.search_radius).
MatchingOptions candidate_reach(const MatchingOptions& options, double error_since, double max_search_radius);

}  // namespace lookahead::slam::segslam
