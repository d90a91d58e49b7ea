// SPDX-License-Identifier: MIT
// The ICP target's nearest-neighbour answers (a dense cell index scanned from the query's own
// cell, skipping cells beyond the best so far) against brute force: ICP must see the same
// correspondences as with the hash grid searched in full.
#include "lookahead/slam/segslam/point_icp3.hpp"

#include <gtest/gtest.h>

#include <random>

namespace lookahead::slam::segslam {
namespace {

// A floor, two walls and scattered clutter, binned at 0.2 m as matching bins its clouds.
Points3 room(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 6.0), h(0.0, 2.5);
  Points3 p;
  for (int k = 0; k < 4000; ++k) {
    p.emplace_back(u(rng), u(rng), 0.0), p.emplace_back(u(rng), 0.0, h(rng)), p.emplace_back(0.0, u(rng), h(rng));
    if (k % 4 == 0) p.emplace_back(u(rng), u(rng), h(rng));
  }
  return bin_points3(p, 0.2);
}

long brute_force_nearest(const IcpTarget3& t, const Eigen::Vector3d& q) {
  long best = -1;
  double best_d2 = t.max_distance() * t.max_distance();
  for (std::size_t j = 0; j < t.size(); ++j) {
    const double d2 = (t.point(static_cast<long>(j)) - q).squaredNorm();
    if (d2 <= best_d2) best_d2 = d2, best = static_cast<long>(j);
  }
  return best;
}

TEST(PointIcp3, TheCellIndexFindsTheBruteForceNearestPoint) {
  std::mt19937_64 rng(5);
  const IcpTarget3 target(room(rng), 0.5);
  std::uniform_real_distribution<double> u(-1.0, 7.0);
  int found = 0;
  for (int k = 0; k < 3000; ++k) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng) * 0.4);
    const long expected = brute_force_nearest(target, q);
    ASSERT_EQ(target.nearest(q), expected) << k;
    found += expected >= 0 ? 1 : 0;
  }
  EXPECT_GT(found, 1000);
  EXPECT_EQ(target.nearest(Eigen::Vector3d(3, 3, 100)), -1);  // beyond the box
}

}  // namespace
}  // namespace lookahead::slam::segslam
