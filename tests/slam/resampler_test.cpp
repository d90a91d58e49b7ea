// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/resampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lookahead::slam {
namespace {

TEST(Resampler, EffectiveSampleSizeSpansOneToN) {
  EXPECT_NEAR(effective_sample_size(normalized_weights({0, 0, 0, 0})), 4.0, 1e-12);
  EXPECT_NEAR(effective_sample_size(normalized_weights({0, -1000, -1000, -1000})), 1.0, 1e-9);
}

TEST(Resampler, NormalizedWeightsSurviveHugeLogWeights) {
  const auto w = normalized_weights({-1e6, -1e6 + std::log(3.0)});
  EXPECT_NEAR(w[0], 0.25, 1e-10);
  EXPECT_NEAR(w[1], 0.75, 1e-10);
}

TEST(Resampler, UniformWeightsKeepEveryParticleOnce) {
  std::mt19937_64 rng(1);
  const auto keep = low_variance_resample(std::vector<double>(10, 0.1), rng);
  for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(keep[i], i);
}

// Low-variance resampling gives each particle floor(N w) or ceil(N w) copies.
TEST(Resampler, CopiesAreProportionalToWeight) {
  std::mt19937_64 rng(9);
  const std::vector<double> w{0.5, 0.25, 0.125, 0.125, 0.0};
  for (int trial = 0; trial < 50; ++trial) {
    const auto keep = low_variance_resample(w, rng);
    ASSERT_EQ(keep.size(), w.size());
    for (std::size_t i = 0; i < w.size(); ++i) {
      const auto copies = static_cast<double>(std::count(keep.begin(), keep.end(), i));
      EXPECT_GE(copies, std::floor(5 * w[i]));
      EXPECT_LE(copies, std::ceil(5 * w[i]));
    }
  }
}

}  // namespace
}  // namespace lookahead::slam
