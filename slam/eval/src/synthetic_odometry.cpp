// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/synthetic_odometry.hpp"

#include <cmath>
#include <random>

namespace lookahead::slam {

std::vector<Pose2> synthesize_odometry(const std::vector<Pose2>& truth, const OdometryDriftModel& m) {
  std::vector<Pose2> odom;
  if (truth.empty()) return odom;
  std::mt19937_64 rng(m.seed);
  std::normal_distribution<double> n(0.0, 1.0);
  double beta = m.k_b * n(rng);
  odom.push_back(truth.front());
  for (std::size_t i = 1; i < truth.size(); ++i) {
    const Pose2 d = truth[i - 1].between(truth[i]);
    const double s = d.norm();
    beta += m.k_bw * s * n(rng);
    const Pose2 noisy{d.x + m.k_t * s * n(rng), d.y + m.k_t * s * n(rng),
                      d.theta + (m.k_r * std::abs(d.theta) + m.k_rt * s) * n(rng) + beta * s};
    odom.push_back(odom.back().compose(noisy));
  }
  return odom;
}

}  // namespace lookahead::slam
