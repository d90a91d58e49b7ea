// SPDX-License-Identifier: MIT
// Correspondence tracking by weighted vote (HybridSLAM sec. 3.1). For each observation every
// particle votes, in proportion to its weight, to ignore it as spurious, to associate it with
// an existing common feature (its landmark's gamma), or to create a new one. The winner
// takes all: every landmark the observation modified or created gets the winning gamma.
#pragma once

#include <vector>

#include "lookahead/slam/hybrid/particle.hpp"

namespace lookahead::slam::hybrid {

/// decisions[p][j]: what particle p did with observation j. New identities are taken from
/// next_id (incremented). Returns the winning gamma per observation (-1: spurious won).
std::vector<long> vote_correspondences(std::vector<Particle>& particles,
                                       const std::vector<std::vector<Decision>>& decisions, long& next_id);

}  // namespace lookahead::slam::hybrid
