// SPDX-License-Identifier: MIT
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

#include <cmath>
#include <stdexcept>

#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {

PreparedScan prepare_scan(const LaserScan& scan, const LikelihoodOptions& options) {
  PreparedScan p;
  p.laser_offset = scan.laser_offset;
  const std::size_t step = static_cast<std::size_t>(std::max(1, options.beam_step));
  for (std::size_t i = 0; i < scan.ranges.size(); i += step) {
    if (!scan.is_return(i) || scan.ranges[i] > options.max_range) continue;
    const double a = scan.bearing(i);
    p.x.push_back(static_cast<float>(scan.ranges[i] * std::cos(a)));
    p.y.push_back(static_cast<float>(scan.ranges[i] * std::sin(a)));
  }
  return p;
}

LikelihoodFieldModel::LikelihoodFieldModel(const LikelihoodOptions& options, const OccupancyGrid& like_grid)
    : options_(options) {
  if (!(options.sigma > 0) || !(options.random_floor > 0 && options.random_floor < 1) ||
      !(options.unknown_likelihood > 0) || !(options.temperature > 0)) {
    throw std::invalid_argument("likelihood: sigma, random_floor, unknown_likelihood, temperature");
  }
  if (!(options.max_range > 0 && options.max_range <= limits::kMaxLaserRange)) {
    throw std::invalid_argument("likelihood: max_range in (0, 1000] m (limits::kMaxLaserRange)");
  }
  const double res = like_grid.resolution();
  const int r2 = like_grid.distance_radius_cells() * like_grid.distance_radius_cells();
  for (int d2 = 0; d2 < 256; ++d2) {
    // Beyond the field radius the distance is unknown but large: score it at the radius.
    const double dist2_m = static_cast<double>(std::min(d2, r2)) * res * res;
    const double p =
        (1.0 - options.random_floor) * std::exp(-dist2_m / (2 * options.sigma * options.sigma)) + options.random_floor;
    log_by_dist2_[static_cast<std::size_t>(d2)] = options.temperature * std::log(p);
  }
  log_unknown_ = options.temperature * std::log(options.unknown_likelihood);
  const double hit_cells = 2.0 * options.sigma / res;
  hit_dist2_ = static_cast<int>(hit_cells * hit_cells);
}

double LikelihoodFieldModel::log_likelihood(const OccupancyGrid& grid, const Pose2& robot, const PreparedScan& scan,
                                            FieldLookup lookup) const {
  const Pose2 laser = robot.compose(scan.laser_offset);
  if (lookup == FieldLookup::kBilinear) return bilinear_log_likelihood(grid, laser, scan);
  const double c = std::cos(laser.theta);
  const double s = std::sin(laser.theta);
  const double inv_res = 1.0 / grid.resolution();
  double sum = 0.0;
  for (std::size_t i = 0; i < scan.x.size(); ++i) {
    const double wx = laser.x + c * scan.x[i] - s * scan.y[i];
    const double wy = laser.y + s * scan.x[i] + c * scan.y[i];
    sum += cell_log_likelihood(grid, static_cast<int>(std::floor(wx * inv_res)),
                               static_cast<int>(std::floor(wy * inv_res)));
  }
  return sum;
}

double LikelihoodFieldModel::cell_log_likelihood(const OccupancyGrid& grid, int cx, int cy) const {
  const GridTile* t = grid.tile(cx >> GridTile::kBits, cy >> GridTile::kBits);
  if (t == nullptr) return log_unknown_;
  const int i_cell = OccupancyGrid::local(CellIndex{cx, cy});
  const int d2 = t->dist2[i_cell];
  return (d2 == GridTile::kFar && t->log_odds[i_cell] == GridTile::kUnknown) ? log_unknown_ : log_by_dist2_[d2];
}

// The field is known at cell centres; between them it is blended, so the score changes with
// every sub-cell move of an end point instead of in steps of a cell (5 cm: at 10 m a step of a
// quarter degree in heading).
double LikelihoodFieldModel::bilinear_log_likelihood(const OccupancyGrid& grid, const Pose2& laser,
                                                     const PreparedScan& scan) const {
  const double c = std::cos(laser.theta);
  const double s = std::sin(laser.theta);
  const double inv_res = 1.0 / grid.resolution();
  double sum = 0.0;
  for (std::size_t i = 0; i < scan.x.size(); ++i) {
    const double u = (laser.x + c * scan.x[i] - s * scan.y[i]) * inv_res - 0.5;
    const double v = (laser.y + s * scan.x[i] + c * scan.y[i]) * inv_res - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const int cx = static_cast<int>(fu), cy = static_cast<int>(fv);
    const double ax = u - fu, ay = v - fv;
    sum += (1 - ay) * ((1 - ax) * cell_log_likelihood(grid, cx, cy) + ax * cell_log_likelihood(grid, cx + 1, cy)) +
           ay * ((1 - ax) * cell_log_likelihood(grid, cx, cy + 1) + ax * cell_log_likelihood(grid, cx + 1, cy + 1));
  }
  return sum;
}

double LikelihoodFieldModel::hit_ratio(const OccupancyGrid& grid, const Pose2& robot, const PreparedScan& scan) const {
  if (scan.x.empty()) return 0.0;
  const Pose2 laser = robot.compose(scan.laser_offset);
  const double c = std::cos(laser.theta);
  const double s = std::sin(laser.theta);
  std::size_t hits = 0;
  for (std::size_t i = 0; i < scan.x.size(); ++i) {
    const CellIndex cell =
        grid.cell_at(laser.x + c * scan.x[i] - s * scan.y[i], laser.y + s * scan.x[i] + c * scan.y[i]);
    hits += grid.dist2(cell) <= hit_dist2_ ? 1 : 0;
  }
  return static_cast<double>(hits) / static_cast<double>(scan.x.size());
}

double LikelihoodFieldModel::end_point_log_likelihood(const OccupancyGrid& grid, double wx, double wy,
                                                      bool& hit) const {
  const CellIndex cell = grid.cell_at(wx, wy);
  const int d2 = grid.dist2(cell);
  hit = d2 <= hit_dist2_;
  if (d2 == GridTile::kFar && !grid.is_known(cell)) return log_unknown_;
  return log_by_dist2_[static_cast<std::size_t>(d2)];
}

}  // namespace lookahead::slam
