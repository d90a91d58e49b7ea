// SPDX-License-Identifier: MIT
#include "lookahead/exploration/lookahead_mapping.hpp"

#include <spdlog/spdlog.h>

namespace lookahead::exploration {

LookaheadMapping::LookaheadMapping(const LookaheadOptions& options, const World& world, const slam::GridOptions& grid,
                                   std::vector<std::uint8_t> observable)
    : options_(options),
      world_(world),
      observable_(std::move(observable)),
      worker_(options.predictor),
      predicted_(grid) {}

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
  if (options_.pictures) pending_map_ = queued_map_;  // copy-on-write: shares the tiles
  pending_ = true;
  due_ = now + options_.latency;
  pending_record_ = PredictionRecord{now, x, y, "", 0.0, 0.0, 0.0, 0.0, {}, std::nullopt};
}

std::shared_ptr<const slam::HypothesisMap> LookaheadMapping::deliver(double now) {
  if (!pending_ || now < due_) return nullptr;
  pending_ = false;
  const std::optional<predictor::Prediction> p = worker_.wait();
  // The record and map of this request, before start_next() overwrites them with the next
  // one's (else every record after the first of a selection would carry the next target's
  // position and time).
  PredictionRecord r = pending_record_;
  const slam::OccupancyGrid map = pending_map_;
  start_next(now);
  if (!p) return nullptr;
  r.status = predictor::to_string(p->status);
  r.psi = p->alignment ? p->alignment->score.psi : 0.0;
  r.area = p->predicted_area;
  r.diameter = p->diameter;
  r.seconds = p->seconds;
  r.alignment = p->alignment;
  if (!p->hypothesis)
    spdlog::debug("t {:.1f}: no hypothesis for ({:.2f}, {:.2f}): {}, best Psi {:.2f}", now, r.x, r.y, r.status, r.psi);
  if (p->hypothesis) {
    r.truth =
        check_against_world(*p->hypothesis, world_, observable_, options_.predictor.features.occupied_threshold, 0.1,
                            options_.predictor.similarity_resolution, options_.predictor.similarity_tolerance_cells);
    predicted_.add(*p->hypothesis);
    if (options_.pictures) snapshots_.push_back({records_.size(), map, *p});
    spdlog::debug(
        "t {:.1f}: hypothesis for ({:.2f}, {:.2f}) Psi {:.2f} ({:.1f} m^2), against the world Psi {:.2f}, "
        "{:.0f}% cells right",
        now, r.x, r.y, r.psi, r.area, r.truth.psi, 100 * r.truth.accuracy());
  }
  records_.push_back(r);
  return p->hypothesis;
}

}  // namespace lookahead::exploration
