// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/resampler.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam {

std::vector<double> normalized_weights(const std::vector<double>& log_weights) {
  std::vector<double> w(log_weights.size());
  if (w.empty()) return w;
  const double max = *std::max_element(log_weights.begin(), log_weights.end());
  double sum = 0.0;
  for (std::size_t i = 0; i < w.size(); ++i) sum += (w[i] = std::exp(log_weights[i] - max));
  for (double& x : w) x /= sum;
  return w;
}

double effective_sample_size(const std::vector<double>& weights) {
  double s = 0.0;
  for (const double x : weights) s += x * x;
  return s > 0 ? 1.0 / s : 0.0;
}

std::vector<std::size_t> low_variance_resample(const std::vector<double>& weights, std::mt19937_64& rng) {
  const std::size_t n = weights.size();
  std::vector<std::size_t> keep;
  keep.reserve(n);
  if (n == 0) return keep;
  const double step = 1.0 / static_cast<double>(n);
  double target = std::uniform_real_distribution<double>(0.0, step)(rng);
  double cumulative = weights[0];
  std::size_t i = 0;
  for (std::size_t m = 0; m < n; ++m) {
    while (target > cumulative && i + 1 < n) cumulative += weights[++i];
    keep.push_back(i);
    target += step;
  }
  return keep;
}

}  // namespace lookahead::slam
