// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/feature_existence.hpp"

#include <algorithm>
#include <stdexcept>

namespace lookahead::slam::hybrid {

FeatureExistence::FeatureExistence(const ExistenceOptions& options) : options_(options) {
  const double c = options.clamp;
  if (!(c > 0.0 && c < 0.5)) throw std::invalid_argument("existence.clamp must be in (0, 0.5)");
  if (!(options.alpha > 0.0 && options.alpha <= 1.0) || !(options.beta >= 0.0 && options.beta < 1.0)) {
    throw std::invalid_argument("existence: need 0 < alpha <= 1 and 0 <= beta < 1");
  }
  if (!(options.prior > 0.0 && options.prior < 1.0)) throw std::invalid_argument("existence.prior must be in (0, 1)");
  alpha_ = std::clamp(options.alpha, c, 1.0 - c);
  beta_ = std::clamp(options.beta, c, 1.0 - c);
}

double FeatureExistence::detected(double p) const {
  return p * alpha_ / (p * alpha_ + (1.0 - p) * beta_);  // HybridSLAM eq. (11)
}

double FeatureExistence::missed(double p) const {
  const double a = 1.0 - alpha_, b = 1.0 - beta_;
  return p * a / (p * a + (1.0 - p) * b);
}

}  // namespace lookahead::slam::hybrid
