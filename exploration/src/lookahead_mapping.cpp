// SPDX-License-Identifier: MIT
#include "lookahead/exploration/lookahead_mapping.hpp"

#include <spdlog/spdlog.h>

namespace lookahead::exploration {

LookaheadMapping::LookaheadMapping(const LookaheadOptions& options, const World& world, const slam::GridOptions& grid)
    : options_(options), world_(world), worker_(options.predictor), predicted_(grid) {}

void LookaheadMapping::request(const slam::OccupancyGrid& map, const std::vector<std::pair<double, double>>& targets,
                               double now) {
  queued_map_ = map;
  queued_.assign(targets.rbegin(), targets.rend());  // popped from the back: first target first
  if (!pending_) start_next(now);
}

void LookaheadMapping::start_next(double now) {
  if (queued_.empty()) return;
  const auto [x, y] = queued_.back();
  queued_.pop_back();
  worker_.request(queued_map_, x, y);
  pending_ = true;
  due_ = now + options_.latency;
  pending_record_ = PredictionRecord{now, x, y, "", 0.0, 0.0, 0.0, {}};
}

std::shared_ptr<const slam::HypothesisMap> LookaheadMapping::deliver(double now) {
  if (!pending_ || now < due_) return nullptr;
  pending_ = false;
  const std::optional<predictor::Prediction> p = worker_.wait();
  start_next(now);
  if (!p) return nullptr;
  PredictionRecord r = pending_record_;
  r.status = predictor::to_string(p->status);
  r.psi = p->alignment ? p->alignment->score.psi : 0.0;
  r.area = p->predicted_area;
  r.seconds = p->seconds;
  if (p->hypothesis) {
    r.truth = check_against_world(*p->hypothesis, world_, options_.predictor.features.occupied_threshold,
                                  0.1, options_.predictor.similarity_resolution,
                                  options_.predictor.similarity_tolerance_cells);
    predicted_.add(*p->hypothesis);
    spdlog::debug("t {:.1f}: hypothesis Psi {:.2f} ({:.1f} m^2), against the world Psi {:.2f}, {:.0f}% cells right",
                  now, r.psi, r.area, r.truth.psi, 100 * r.truth.accuracy());
  }
  records_.push_back(r);
  return p->hypothesis;
}

}  // namespace lookahead::exploration
