// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/map_divergence.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lookahead::slam {
namespace {

ProbabilityMap map_of(std::vector<double> p, double origin_x = 0.0) {
  ProbabilityMap m;
  m.width = static_cast<int>(p.size());
  m.height = 1;
  m.resolution = 1.0;
  m.origin_x = origin_x;
  m.p = std::move(p);
  return m;
}

TEST(MapDivergence, ZeroForTheSameMapAndBernoulliKlOtherwise) {
  const ProbabilityMap a = map_of({0.9, 0.1, -1.0});
  EXPECT_DOUBLE_EQ(map_divergence(a, a).total, 0.0);
  EXPECT_EQ(map_divergence(a, a).compared, 2u);  // the unknown cell is left out
  const ProbabilityMap b = map_of({0.5, 0.1, 0.7});
  const double expected = 0.9 * std::log(0.9 / 0.5) + 0.1 * std::log(0.1 / 0.5);
  EXPECT_NEAR(map_divergence(a, b).total, expected, 1e-12);
  EXPECT_GT(map_divergence(b, a).total, 0.0);  // not symmetric, but positive both ways
}

TEST(MapDivergence, ComparesTheSamePlaceWhenOriginsDiffer) {
  const ProbabilityMap a = map_of({0.9, 0.1});
  const ProbabilityMap shifted = map_of({-1.0, 0.9, 0.1}, -1.0);  // one unknown cell first
  EXPECT_DOUBLE_EQ(map_divergence(a, shifted).total, 0.0);
  EXPECT_EQ(map_divergence(a, shifted).compared, 2u);
}

}  // namespace
}  // namespace lookahead::slam
