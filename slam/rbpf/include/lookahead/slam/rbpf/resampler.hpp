// SPDX-License-Identifier: MIT
// Effective sample size and low-variance (systematic) resampling
// (Thrun, Burgard, Fox, Probabilistic Robotics, table 4.4).
#pragma once

#include <algorithm>
#include <random>
#include <vector>

namespace lookahead::slam {

/// Normalised weights from log weights (max-shifted, so no underflow of the best).
std::vector<double> normalized_weights(const std::vector<double>& log_weights);
/// N_eff = 1 / sum w_i^2 of normalised weights (Grisetti 2007 eq. (20)).
double effective_sample_size(const std::vector<double>& weights);
/// Indices of the particles to keep, one draw of a single uniform offset.
std::vector<std::size_t> low_variance_resample(const std::vector<double>& weights, std::mt19937_64& rng);

/// Selective resampling (Grisetti et al. 2007, sec. IV step 5) of particles of any type with a
/// `log_weight`: shifts the log weights by their max (ratios unchanged, values small), and
/// when N_eff < threshold * N draws a new set (weights reset; maps are copied by handle).
/// Returns N_eff before resampling; `resampled` says whether it resampled.
template <class Particle>
double resample_if_degenerate(std::vector<Particle>& particles, double threshold, std::mt19937_64& rng,
                              bool& resampled) {
  std::vector<double> logw(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) logw[i] = particles[i].log_weight;
  const std::vector<double> w = normalized_weights(logw);
  const double neff = effective_sample_size(w);
  const double max_logw = *std::max_element(logw.begin(), logw.end());
  for (Particle& p : particles) p.log_weight -= max_logw;
  resampled = !(neff >= threshold * static_cast<double>(particles.size()));
  if (!resampled) return neff;
  std::vector<Particle> next;
  next.reserve(particles.size());
  for (const std::size_t k : low_variance_resample(w, rng)) next.push_back(particles[k]);
  for (Particle& p : next) p.log_weight = 0.0;
  particles = std::move(next);
  return neff;
}

}  // namespace lookahead::slam
