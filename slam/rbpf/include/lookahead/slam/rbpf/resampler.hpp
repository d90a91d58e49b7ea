// SPDX-License-Identifier: MIT
// Effective sample size and low-variance (systematic) resampling
// (Thrun, Burgard, Fox, Probabilistic Robotics, table 4.4).
#pragma once

#include <random>
#include <vector>

namespace lookahead::slam {

/// Normalised weights from log weights (max-shifted, so no underflow of the best).
std::vector<double> normalized_weights(const std::vector<double>& log_weights);
/// N_eff = 1 / sum w_i^2 of normalised weights (Grisetti 2007 eq. (20)).
double effective_sample_size(const std::vector<double>& weights);
/// Indices of the particles to keep, one draw of a single uniform offset.
std::vector<std::size_t> low_variance_resample(const std::vector<double>& weights, std::mt19937_64& rng);

}  // namespace lookahead::slam
