// SPDX-License-Identifier: MIT
#include "lookahead/pipeline/slam_lookahead.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lookahead/slam/grid/frontier_cell.hpp"

namespace lookahead::pipeline {

std::vector<std::pair<double, double>> frontiers_ahead(const slam::OccupancyGrid& map, const slam::Pose2& pose,
                                                       double range, double half_angle, int max_count, double spacing,
                                                       double free_threshold) {
  const slam::CellIndex lo = map.cell_at(pose.x - range, pose.y - range);
  const slam::CellIndex hi = map.cell_at(pose.x + range, pose.y + range);
  std::vector<std::pair<double, std::pair<double, double>>> found;  // (distance, cell centre)
  // The plain rule: a free cell next to never-seen space.
  slam::FrontierCellRule rule;
  rule.free_threshold = free_threshold;
  const slam::FrontierCellTest frontier(rule);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!frontier.is_frontier(map, {x, y})) continue;
      double cx = 0, cy = 0;
      map.cell_center({x, y}, cx, cy);
      const double d = std::hypot(cx - pose.x, cy - pose.y);
      if (d > range) continue;
      if (std::abs(slam::normalize_angle(std::atan2(cy - pose.y, cx - pose.x) - pose.theta)) > half_angle) continue;
      found.push_back({d, {cx, cy}});
    }
  }
  std::sort(found.begin(), found.end());  // by distance, then position: no ties left to chance
  std::vector<std::pair<double, double>> out;
  for (const auto& [d, c] : found) {
    if (static_cast<int>(out.size()) >= max_count) break;
    const bool apart = std::all_of(out.begin(), out.end(), [&](const std::pair<double, double>& o) {
      return std::hypot(o.first - c.first, o.second - c.second) >= spacing;
    });
    if (apart) out.push_back(c);
  }
  return out;
}

std::optional<std::pair<double, double>> frontier_ahead(const slam::OccupancyGrid& map, const slam::Pose2& pose,
                                                        double range, double half_angle, double free_threshold) {
  const auto all = frontiers_ahead(map, pose, range, half_angle, 1, 0.0, free_threshold);
  if (all.empty()) return std::nullopt;
  return all.front();
}

SlamLookahead::SlamLookahead(const predictor::PredictorOptions& predictor, const SlamLookaheadOptions& options)
    : options_(options),
      worker_(predictor, options.wait_for_predictions ? predictor::PredictionWorker::Priority::kNormal
                                                      : predictor::PredictionWorker::Priority::kBackground) {}

void SlamLookahead::after_update(slam::Rbpf& filter) {
  ++updates_;
  if (due_ >= 0 && updates_ >= due_) {
    // Live (no waiting), the filter never stalls (measured: waiting for 55 ms predictions
    // cost fr101 40 % of its update rate): a prediction not finished yet is taken later.
    std::optional<predictor::Prediction> p = options_.wait_for_predictions ? worker_.wait() : worker_.poll();
    if (!p) {
      if (worker_.busy()) return;
      p = worker_.poll();  // it finished between the two calls
    }
    due_ = -1;
    if (p) {
      stats_.seconds += p->seconds;
      stats_.no_control_point += p->status == predictor::Prediction::Status::kNoControlPoint;
      stats_.no_match += p->status == predictor::Prediction::Status::kNoMatch;
      LogPredictionRecord r{updates_, p->target_x, p->target_y, p->status};
      if (p->alignment) r.psi = p->alignment->score.psi, r.conflict_share = p->alignment->score.conflict_share();
      r.predicted_area = p->predicted_area;
      stats_.records.push_back(r);
      spdlog::debug("prediction at ({:.2f}, {:.2f}): {}, best Psi {:.3f}, conflicts {:.3f}, {} transforms, {:.1f} m^2",
                    r.x, r.y, to_string(r.status), r.psi, r.conflict_share, p->candidates, r.predicted_area);
      if (p->hypothesis) {
        ++stats_.hypotheses;
        filter.add_hypothesis(p->hypothesis);
      }
    }
  }
  if (due_ >= 0 || updates_ % options_.period_updates != 0) return;
  const slam::Particle& best = filter.particles()[filter.best_particle()];
  auto targets = frontiers_ahead(best.map, best.pose, options_.range, options_.half_angle, options_.max_candidates,
                                 options_.candidate_spacing);
  if (targets.empty()) return;
  worker_.request(best.map, std::move(targets));
  ++stats_.requests;
  due_ = updates_ + options_.latency_updates;
}

}  // namespace lookahead::pipeline
