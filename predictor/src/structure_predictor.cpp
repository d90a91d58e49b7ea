// SPDX-License-Identifier: MIT
#include "lookahead/predictor/structure_predictor.hpp"

#include <chrono>
#include <cmath>
#include <limits>

namespace lookahead::predictor {
namespace {

// The control point: the corner nearest the target within the preset range (sec. III-A).
std::optional<Corner> control_point(const std::vector<Corner>& corners, double tx, double ty, double range) {
  std::optional<Corner> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (const Corner& c : corners) {
    const double d = std::hypot(c.x - tx, c.y - ty);
    if (d <= range && d < best_d) {
      best = c;
      best_d = d;
    }
  }
  return best;
}

double cell_area(const slam::OccupancyGrid& g) { return g.resolution() * g.resolution(); }

}  // namespace

const char* to_string(Prediction::Status status) {
  switch (status) {
    case Prediction::Status::kPredicted:
      return "predicted";
    case Prediction::Status::kNoControlPoint:
      return "no_control_point";
    case Prediction::Status::kNoMatch:
      return "no_match";
  }
  return "?";
}

std::shared_ptr<slam::HypothesisMap> make_hypothesis(const slam::OccupancyGrid& map, double tx, double ty,
                                                     double diameter, const slam::Pose2& reference_to_target) {
  auto h = std::make_shared<slam::HypothesisMap>();
  h->grid = slam::OccupancyGrid(map.options());
  const slam::Pose2 inv = reference_to_target.inverse();
  for (const slam::CellIndex c : unexplored_region(map, tx, ty, diameter)) {
    double x = 0, y = 0;
    map.cell_center(c, x, y);
    const slam::Pose2 q = inv.compose(slam::Pose2{x, y, 0.0});
    const std::int16_t l = map.raw_log_odds(map.cell_at(q.x, q.y));
    if (l != slam::GridTile::kUnknown) h->grid.add_log_odds(c, l);
  }
  return h;
}

ExploredMapModel model_explored_map(const slam::OccupancyGrid& map, const PredictorOptions& o) {
  return {extract_features(map, o.features),
          CoarseOccupancy(map, o.similarity_resolution, o.features.occupied_threshold, o.similarity_tolerance_cells)};
}

Prediction predict_structure(const slam::OccupancyGrid& map, double tx, double ty, const PredictorOptions& o) {
  validate(o);
  const auto t0 = std::chrono::steady_clock::now();
  Prediction p = predict_structure(map, model_explored_map(map, o), tx, ty, o);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

namespace {

// One registration of the surroundings of diameter o.surroundings_diameter (sec. III).
Prediction predict_at_scale(const slam::OccupancyGrid& map, const ExploredMapModel& model, double tx, double ty,
                            const PredictorOptions& o) {
  Prediction p;
  p.target_x = tx;
  p.target_y = ty;
  p.diameter = o.surroundings_diameter;
  p.features = model.features;
  const std::optional<Corner> control = control_point(p.features.corners, tx, ty, o.control_point_range);
  if (!control) return p;
  const RegionSamples region = disc_samples(tx, ty, o.surroundings_diameter, o.similarity_resolution);
  const Registration reg = register_region(model.coarse, region, *control, p.features.corners, o);
  p.alignment = reg.best;
  p.candidates = reg.candidates;
  p.status = Prediction::Status::kNoMatch;
  if (!reg.best || reg.best->score.psi < o.similarity_threshold) return p;
  auto h = make_hypothesis(map, tx, ty, o.surroundings_diameter, reg.best->reference_to_target);
  h->similarity = reg.best->score.psi;
  slam::CellIndex lo, hi;
  std::size_t cells = 0;
  if (h->grid.known_bounds(lo, hi)) {
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) cells += h->grid.is_known({x, y});
  }
  p.predicted_area = static_cast<double>(cells) * cell_area(map);
  if (p.predicted_area >= o.min_predicted_area) {
    p.hypothesis = std::move(h);
    p.status = Prediction::Status::kPredicted;
  }
  return p;
}

}  // namespace

Prediction predict_structure(const slam::OccupancyGrid& map, const ExploredMapModel& model, double tx, double ty,
                             const PredictorOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  Prediction p;
  if (o.large_surroundings_diameter > 0) {
    PredictorOptions large = o;
    large.surroundings_diameter = o.large_surroundings_diameter;
    large.max_conflict_share = o.large_max_conflict_share;
    p = predict_at_scale(map, model, tx, ty, large);
  }
  // Without a control point the surroundings of diameter d have none either (the same range,
  // the same corners).
  if (o.large_surroundings_diameter <= 0 || p.status == Prediction::Status::kNoMatch) {
    p = predict_at_scale(map, model, tx, ty, o);
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace lookahead::predictor
