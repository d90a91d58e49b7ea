// SPDX-License-Identifier: MIT
// Probability of existence of a feature (HybridSLAM sec. 5.1 HybridSLAM eq. (11), after Stone et al.,
// "Bayesian Multiple Target Tracking"): a detection multiplies the odds by alpha / beta, a
// missed detection of a feature in view by (1 - alpha) / (1 - beta).
#pragma once

#include "lookahead/slam/hybrid/hybrid_options.hpp"

namespace lookahead::slam::hybrid {

class FeatureExistence {
 public:
  explicit FeatureExistence(const ExistenceOptions& options);
  /// HybridSLAM eq. (11): p <- p alpha / (p alpha + (1 - p) beta).
  [[nodiscard]] double detected(double p) const;
  /// The complementary update for a feature in view that was not detected.
  [[nodiscard]] double missed(double p) const;
  /// Existence of a feature just created by one observation.
  [[nodiscard]] double created() const { return detected(options_.prior); }
  [[nodiscard]] const ExistenceOptions& options() const { return options_; }
  [[nodiscard]] double alpha() const { return alpha_; }  ///< clamped
  [[nodiscard]] double beta() const { return beta_; }    ///< clamped

 private:
  ExistenceOptions options_;
  double alpha_, beta_;  // clamped (see ExistenceOptions::clamp)
};

}  // namespace lookahead::slam::hybrid
