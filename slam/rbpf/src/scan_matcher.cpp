// SPDX-License-Identifier: MIT
#include "lookahead/slam/rbpf/scan_matcher.hpp"

#include <array>

namespace lookahead::slam {

MatchResult ScanMatcher::match(const OccupancyGrid& grid, const Pose2& start, const PreparedScan& scan,
                               double angular_reach, FieldLookup lookup) const {
  MatchResult r;
  r.pose = start;
  r.log_likelihood = model_.log_likelihood(grid, start, scan, lookup);
  r.evaluations = 1;
  double lin = options_.linear_step;
  // A first angular step of one rotation std of the odometry: a hill climb that starts
  // finer stops on the first local optimum near a misread turn and the particle keeps the
  // turn the odometry reported. The extra levels keep the finest step as configured.
  double ang = options_.angular_step;
  int levels = options_.refinements;
  while (ang < angular_reach) {
    ang *= 2.0;
    ++levels;
  }
  int moves = 0;
  for (int level = 0; level <= levels && moves < options_.max_iterations; ++level) {
    bool improved = true;
    while (improved && moves < options_.max_iterations) {
      improved = false;
      // Steps along the robot's own axes: odometry errs mostly along and across the heading.
      const double c = std::cos(r.pose.theta), s = std::sin(r.pose.theta);
      const std::array<Pose2, 6> steps{{{lin * c, lin * s, 0},
                                        {-lin * c, -lin * s, 0},
                                        {-lin * s, lin * c, 0},
                                        {lin * s, -lin * c, 0},
                                        {0, 0, ang},
                                        {0, 0, -ang}}};
      Pose2 best = r.pose;
      double best_ll = r.log_likelihood;
      for (const Pose2& d : steps) {
        const Pose2 candidate{r.pose.x + d.x, r.pose.y + d.y, normalize_angle(r.pose.theta + d.theta)};
        const double ll = model_.log_likelihood(grid, candidate, scan, lookup);
        ++r.evaluations;
        if (ll > best_ll) {
          best_ll = ll;
          best = candidate;
        }
      }
      if (best_ll > r.log_likelihood) {
        r.pose = best;
        r.log_likelihood = best_ll;
        improved = true;
        ++moves;
      }
    }
    if (ang <= options_.angular_step) lin *= 0.5;
    ang *= 0.5;
  }
  r.hit_ratio = model_.hit_ratio(grid, r.pose, scan);
  r.ok = r.hit_ratio >= options_.min_hit_ratio &&
         std::hypot(r.pose.x - start.x, r.pose.y - start.y) <= options_.max_correction;
  return r;
}

}  // namespace lookahead::slam
