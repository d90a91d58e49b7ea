// SPDX-License-Identifier: MIT
#include "lookahead/exploration/hypothesis_check.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "lookahead/predictor/similarity.hpp"

namespace lookahead::exploration {
namespace {

bool wall_near(const World& world, double x, double y, double tolerance) {
  const int r = static_cast<int>(std::ceil(tolerance / world.resolution()));
  const slam::CellIndex c = world.cell_of({x, y});
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (world.is_occupied(slam::CellIndex{c.x + dx, c.y + dy})) return true;
  return false;
}

bool is_observable(const World& world, const std::vector<std::uint8_t>& observable, double x, double y) {
  if (observable.empty()) return true;
  const slam::CellIndex c = world.cell_of({x, y});
  return world.contains(c) && observable[static_cast<std::size_t>(c.y) * world.width() + c.x] != 0;
}

// The world over the hypothesis' extent as a grid, for Psi: the map a complete exploration
// would build. Cells no robot observes stay unknown, so they hold no wall: the paper scored
// its hypotheses against the final built map (sec. V-A.2), which has no walls beyond the
// outer ones or inside thick walls, while our worlds are solid there (a KTH plan's outside,
// everything beyond a generated floor's raster). Scored against those solid cells, a right
// hypothesis that reaches past an unseen outer wall looked wrong.
slam::OccupancyGrid world_grid(const slam::HypothesisMap& h, const World& world,
                               const std::vector<std::uint8_t>& observable, slam::CellIndex lo, slam::CellIndex hi) {
  slam::OccupancyGrid g(h.grid.options());
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      double cx = 0, cy = 0;
      g.cell_center({x, y}, cx, cy);
      if (!is_observable(world, observable, cx, cy)) continue;
      g.add_log_odds({x, y}, world.is_occupied(cx, cy) ? 3000 : -1000);
    }
  }
  return g;
}

predictor::SimilarityScore psi_against(const predictor::CoarseOccupancy& predicted, const slam::OccupancyGrid& truth,
                                       const predictor::RegionSamples& region, double occupied_threshold,
                                       double similarity_resolution, int similarity_tolerance_cells) {
  const predictor::CoarseOccupancy coarse(truth, similarity_resolution, occupied_threshold, similarity_tolerance_cells);
  return predictor::similarity(predicted, coarse, region, {});
}

}  // namespace

bool prediction_matches_world(bool predicted_wall, const World& world, double x, double y, double wall_tolerance) {
  return predicted_wall ? wall_near(world, x, y, wall_tolerance) : !world.is_occupied(x, y);
}

HypothesisCheck check_against_world(const slam::HypothesisMap& h, const World& world,
                                    const std::vector<std::uint8_t>& observable, double occupied_threshold,
                                    double wall_tolerance, double similarity_resolution,
                                    int similarity_tolerance_cells) {
  HypothesisCheck check;
  slam::CellIndex lo, hi;
  if (!h.grid.known_bounds(lo, hi)) return check;
  predictor::RegionSamples region;  // the coarse samples the hypothesis covers
  const predictor::CoarseOccupancy predicted(h.grid, similarity_resolution, occupied_threshold,
                                             similarity_tolerance_cells);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!h.grid.is_known({x, y})) continue;
      double cx = 0, cy = 0;
      h.grid.cell_center({x, y}, cx, cy);
      ++check.cells;
      const bool wall = h.grid.probability({x, y}) >= occupied_threshold;
      const bool right = prediction_matches_world(wall, world, cx, cy, wall_tolerance);
      check.correct += right;
      check.wall_cells += wall;
      check.walls_correct += wall && right;
    }
  }
  const double res = similarity_resolution;
  for (double y = (lo.y + 0.5) * h.grid.resolution(); y < (hi.y + 1) * h.grid.resolution(); y += res) {
    for (double x = (lo.x + 0.5) * h.grid.resolution(); x < (hi.x + 1) * h.grid.resolution(); x += res) {
      if (!predicted.known(x, y)) continue;
      region.x.push_back(x);
      region.y.push_back(y);
    }
  }
  const predictor::SimilarityScore score = psi_against(predicted, world_grid(h, world, observable, lo, hi), region,
                                                       occupied_threshold, res, similarity_tolerance_cells);
  check.psi = score.psi;
  check.predicted_walls = score.target_occupied;
  check.world_walls = score.reference_occupied;
  check.psi_solid_world = psi_against(predicted, world_grid(h, world, {}, lo, hi), region, occupied_threshold, res,
                                      similarity_tolerance_cells)
                              .psi;
  return check;
}

void score_prediction_in_use(const PredictedMap& look_ahead, const slam::OccupancyGrid& map, const World& world,
                             const std::vector<std::uint8_t>& observable, double occupied_threshold,
                             PredictionInUse& in_use) {
  const slam::OccupancyGrid& cells = look_ahead.cells();
  slam::CellIndex lo, hi;
  if (!cells.known_bounds(lo, hi)) return;
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if (!look_ahead.predicted(map, {x, y})) continue;
      double cx = 0, cy = 0;
      cells.cell_center({x, y}, cx, cy);
      if (!is_observable(world, observable, cx, cy)) continue;
      const bool wall = cells.probability({x, y}) >= occupied_threshold;
      const bool right = prediction_matches_world(wall, world, cx, cy);
      ++in_use.cells;
      in_use.correct += right;
      in_use.wall_cells += wall;
      in_use.walls_correct += wall && right;
    }
  }
}

}  // namespace lookahead::exploration
