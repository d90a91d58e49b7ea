// SPDX-License-Identifier: MIT
#include "lookahead/exploration/hypothesis_check.hpp"

#include <cmath>

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

// The world over the hypothesis' extent as a grid, for Psi.
slam::OccupancyGrid world_grid(const slam::HypothesisMap& h, const World& world, slam::CellIndex lo,
                               slam::CellIndex hi) {
  slam::OccupancyGrid g(h.grid.options());
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      double cx = 0, cy = 0;
      g.cell_center({x, y}, cx, cy);
      g.add_log_odds({x, y}, world.is_occupied(cx, cy) ? 3000 : -1000);
    }
  }
  return g;
}

}  // namespace

bool prediction_matches_world(bool predicted_wall, const World& world, double x, double y, double wall_tolerance) {
  return predicted_wall ? wall_near(world, x, y, wall_tolerance) : !world.is_occupied(x, y);
}

HypothesisCheck check_against_world(const slam::HypothesisMap& h, const World& world, double occupied_threshold,
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
      check.correct += prediction_matches_world(wall, world, cx, cy, wall_tolerance);
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
  const predictor::CoarseOccupancy truth(world_grid(h, world, lo, hi), res, occupied_threshold,
                                         similarity_tolerance_cells);
  check.psi = predictor::similarity(predicted, truth, region, {}).psi;
  return check;
}

}  // namespace lookahead::exploration
