// SPDX-License-Identifier: MIT
#include "lookahead/predictor/structure_predictor.hpp"

#include <algorithm>
#include <array>
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
    case Prediction::Status::kPredicted: return "predicted";
    case Prediction::Status::kNoControlPoint: return "no_control_point";
    case Prediction::Status::kNoMatch: return "no_match";
  }
  return "?";
}

std::vector<slam::CellIndex> unexplored_region(const slam::OccupancyGrid& map, double tx, double ty, double diameter) {
  const double r = diameter / 2;
  const slam::CellIndex t = map.cell_at(tx, ty);
  const int r_cells = static_cast<int>(std::ceil(r / map.resolution()));
  const int seed_cells =
      std::min(r_cells, static_cast<int>(std::ceil(kSeedRadius / map.resolution())));
  const int side = 2 * r_cells + 1;
  enum Mark : char { kNew = 0, kPassed = 1, kInRegion = 2 };
  std::vector<char> seen(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), kNew);
  const auto within = [&](slam::CellIndex c, int radius) {
    const int dx = c.x - t.x, dy = c.y - t.y;
    return dx * dx + dy * dy <= radius * radius;
  };
  const auto mark = [&](slam::CellIndex c) -> char& {
    return seen[static_cast<std::size_t>((c.y - t.y + r_cells) * side + (c.x - t.x + r_cells))];
  };
  const auto neighbours = [](slam::CellIndex c) {
    return std::array<slam::CellIndex, 4>{
        slam::CellIndex{c.x + 1, c.y}, slam::CellIndex{c.x - 1, c.y}, slam::CellIndex{c.x, c.y + 1},
        slam::CellIndex{c.x, c.y - 1}};
  };
  // Seeds: the unknown cells within kSeedRadius that f reaches without crossing a wall
  // (4-connected through free and unknown cells; a mapped wall line is 8-connected, so it
  // stops the fill). The goal stands on free space near the frontier, not on it, hence the
  // radius. Until 2026-11-22 every unknown cell within the radius seeded the region, so a
  // target by a seen outer wall seeded the unknown space behind it, and the hypothesis
  // predicted a whole room outside the building (the office study's lowest Psi).
  std::vector<slam::CellIndex> passed{t}, region;
  mark(t) = kPassed;
  for (std::size_t i = 0; i < passed.size(); ++i) {
    for (const slam::CellIndex n : neighbours(passed[i])) {
      if (!within(n, seed_cells) || mark(n) != kNew) continue;
      if (!map.is_known(n)) {
        mark(n) = kInRegion;
        region.push_back(n);
      } else if (map.raw_log_odds(n) <= 0) {  // free (or undecided): the fill passes
        mark(n) = kPassed;
        passed.push_back(n);
      }
    }
  }
  for (std::size_t i = 0; i < region.size(); ++i) {  // breadth-first through unknown cells
    for (const slam::CellIndex n : neighbours(region[i])) {
      if (!within(n, r_cells) || mark(n) == kInRegion || map.is_known(n)) continue;
      mark(n) = kInRegion;
      region.push_back(n);
    }
  }
  return region;
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

Prediction predict_structure(const slam::OccupancyGrid& map, const ExploredMapModel& model, double tx, double ty,
                             const PredictorOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  Prediction p;
  p.target_x = tx;
  p.target_y = ty;
  p.features = model.features;
  const std::optional<Corner> control = control_point(p.features.corners, tx, ty, o.control_point_range);
  if (control) {
    const RegionSamples region = disc_samples(tx, ty, o.surroundings_diameter, o.similarity_resolution);
    const Registration reg = register_region(model.coarse, region, *control, p.features.corners, o);
    p.alignment = reg.best;
    p.candidates = reg.candidates;
    p.status = Prediction::Status::kNoMatch;
    if (reg.best && reg.best->score.psi >= o.similarity_threshold) {
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
    }
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return p;
}

}  // namespace lookahead::predictor
