// SPDX-License-Identifier: MIT
#include "lookahead/predictor/slam_lookahead.hpp"

#include <cmath>
#include <limits>

namespace lookahead::predictor {

std::optional<std::pair<double, double>> frontier_ahead(const slam::OccupancyGrid& map, const slam::Pose2& pose,
                                                        double range, double half_angle, double free_threshold) {
  const slam::CellIndex lo = map.cell_at(pose.x - range, pose.y - range);
  const slam::CellIndex hi = map.cell_at(pose.x + range, pose.y + range);
  std::optional<std::pair<double, double>> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const slam::CellIndex c{x, y};
      if (!map.is_known(c) || map.probability(c) >= free_threshold) continue;
      if (map.is_known({x + 1, y}) && map.is_known({x - 1, y}) && map.is_known({x, y + 1}) && map.is_known({x, y - 1})) {
        continue;
      }
      double cx = 0, cy = 0;
      map.cell_center(c, cx, cy);
      const double d = std::hypot(cx - pose.x, cy - pose.y);
      if (d > range || d >= best_d) continue;
      if (std::abs(slam::normalize_angle(std::atan2(cy - pose.y, cx - pose.x) - pose.theta)) > half_angle) continue;
      best = std::pair<double, double>{cx, cy};
      best_d = d;
    }
  }
  return best;
}

SlamLookahead::SlamLookahead(const PredictorOptions& predictor, const SlamLookaheadOptions& options)
    : options_(options), worker_(predictor) {}

void SlamLookahead::after_update(slam::Rbpf& filter) {
  ++updates_;
  if (due_ >= 0 && updates_ >= due_) {
    // The filter never waits (measured: waiting for 55 ms predictions cost fr101 40 % of its
    // update rate): a prediction not finished yet is taken at a later update.
    std::optional<Prediction> p = options_.reproducible ? worker_.wait() : worker_.poll();
    if (!p) {
      if (worker_.busy()) return;
      p = worker_.poll();  // it finished between the two calls
    }
    due_ = -1;
    if (p) {
      stats_.seconds += p->seconds;
      stats_.no_control_point += p->status == Prediction::Status::kNoControlPoint;
      stats_.no_match += p->status == Prediction::Status::kNoMatch;
      if (p->hypothesis) {
        ++stats_.hypotheses;
        filter.add_hypothesis(p->hypothesis);
      }
    }
  }
  if (due_ >= 0 || updates_ % options_.period_updates != 0) return;
  const slam::Particle& best = filter.particles()[filter.best_particle()];
  const auto target = frontier_ahead(best.map, best.pose, options_.range, options_.half_angle);
  if (!target) return;
  worker_.request(best.map, target->first, target->second);
  ++stats_.requests;
  due_ = updates_ + options_.latency_updates;
}

}  // namespace lookahead::predictor
