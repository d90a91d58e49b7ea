// SPDX-License-Identifier: MIT
// FastSLAM 2.0 with unknown data association (Montemerlo, Thrun et al. 2003/2004), the
// front-end of HybridSLAM (Brooks & Bailey, HybridSLAM sec. 2-3, 5.1):
//  - per particle, each observation's association is *sampled* (data association
//    sampling) among the gated features, "a new feature" and "spurious", from the
//    predictive likelihoods under the particle's pose proposal;
//  - the pose is drawn from the proposal refined by the sampled associations;
//  - landmark EKFs, a probability of existence per feature (HybridSLAM eq. (11)), culling;
//  - correspondence variables kept consistent across particles by weighted vote (HybridSLAM sec. 3.1);
//  - conversion of the particle set to one Gaussian by moment matching (HybridSLAM eq. (6)-(7), HybridSLAM sec. 3.2).
#pragma once

#include <random>
#include <vector>

#include "lookahead/slam/hybrid/feature_existence.hpp"
#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/local_front_end.hpp"
#include "lookahead/slam/hybrid/particle.hpp"

namespace lookahead::slam::hybrid {

class FastSlam final : public LocalFrontEnd {
 public:
  FastSlam(const HybridOptions& options, std::uint64_t seed);

  void predict(const MotionStep& step) override;
  void observe(const std::vector<RangeBearing>& observations) override;
  [[nodiscard]] PoseGaussian vehicle() const override;
  [[nodiscard]] GaussianMap to_gaussian(double min_existence) override;
  void restart() override;

  [[nodiscard]] const std::vector<Particle>& particles() const { return particles_; }
  [[nodiscard]] std::size_t resamplings() const { return resamplings_; }

 private:
  /// One particle's DAS, proposal, pose draw and landmark updates; returns log weight factor.
  double update_particle(Particle& p, const std::vector<RangeBearing>& z, std::vector<Decision>& decisions);
  void apply_missed_detections(Particle& p, const std::vector<Decision>& decisions) const;
  void cull();
  void resample_if_degenerate();

  HybridOptions options_;
  FeatureExistence existence_;
  std::vector<Particle> particles_;
  MotionStep pending_;
  bool has_pending_ = false;
  std::mt19937_64 rng_;
  long next_id_ = 0;  // correspondence variables handed out so far
  std::size_t resamplings_ = 0;
};

}  // namespace lookahead::slam::hybrid
