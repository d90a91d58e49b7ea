// SPDX-License-Identifier: MIT
// Conversion of the FastSLAM particle set to one Gaussian by moment matching (HybridSLAM
// HybridSLAM eq. (6)-(7)) over the common feature set given by the correspondence variables (HybridSLAM sec. 3.2).
#pragma once

#include <random>
#include <vector>

#include "lookahead/slam/hybrid/gaussian_map.hpp"
#include "lookahead/slam/hybrid/particle.hpp"

namespace lookahead::slam::hybrid {

/// Probability of existence of every common feature: the weighted sum over particles of
/// their landmark's existence, a particle without the feature counting 0 (HybridSLAM sec. 3.2, last
/// paragraph). Returns (id, existence) sorted by id.
struct CommonFeature {
  long id = -1;
  double existence = 0.0;
};
std::vector<CommonFeature> common_features(const std::vector<Particle>& particles);

/// The Gaussian over the vehicle and the common features whose existence exceeds
/// `min_existence`. Corner cases of HybridSLAM sec. 3.2: a particle holding several landmarks with one
/// gamma contributes one of them chosen at random (`rng`); a particle holding none is
/// ignored for that feature. Weights need not be normalised.
GaussianMap moment_match(const std::vector<Particle>& particles, double min_existence, std::mt19937_64& rng);

/// The vehicle pose alone (what the failure test and the plots read every step).
PoseGaussian moment_match_pose(const std::vector<Particle>& particles);

}  // namespace lookahead::slam::hybrid
