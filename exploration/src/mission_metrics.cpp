// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {

CoverageMeter::CoverageMeter(const World& world, const ReachableArea& area) {
  const int step = std::max(1, static_cast<int>(std::lround(0.1 / world.resolution())));
  for (int y = 0; y < world.height(); y += step) {
    for (int x = 0; x < world.width(); x += step) {
      if (!area.reachable[static_cast<std::size_t>(y) * static_cast<std::size_t>(world.width()) +
                          static_cast<std::size_t>(x)]) {
        continue;
      }
      const Eigen::Vector2d c = world.center_of({x, y});
      points_.push_back({c.x(), c.y()});
    }
  }
}

double CoverageMeter::coverage(const slam::OccupancyGrid& map) const { return coverage(map, nullptr); }

double CoverageMeter::coverage(const slam::OccupancyGrid& map,
                               const std::function<bool(double, double)>& also_covered) const {
  if (points_.empty()) return 0.0;
  std::size_t known = 0;
  for (const auto& [x, y] : points_) {
    const slam::CellIndex c = map.cell_at(x, y);
    // Explored means observed, whatever the evidence says: a free cell beside a wall that the
    // beam ends blur towards occupied was seen all the same, and no second look changes that.
    if (map.is_known(c) || (also_covered && also_covered(x, y))) ++known;
  }
  return static_cast<double>(known) / static_cast<double>(points_.size());
}

std::array<Milestone, 3> coverage_milestones(const std::vector<CoverageSample>& curve) {
  std::array<Milestone, 3> m{{{0.90}, {0.95}, {0.99}}};
  for (Milestone& ms : m) {
    const auto it =
        std::find_if(curve.begin(), curve.end(), [&](const CoverageSample& s) { return s.coverage >= ms.level; });
    if (it == curve.end()) continue;
    ms.reached = true;
    ms.time = it->time;
    ms.path_length = it->path_length;
  }
  return m;
}

namespace {

bool world_obstacle_near(const World& world, slam::CellIndex c, int r) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (world.is_occupied(slam::CellIndex{c.x + dx, c.y + dy})) return true;
  return false;
}

bool map_obstacle_near(const slam::OccupancyGrid& map, double x, double y, double radius, double threshold) {
  const slam::CellIndex c = map.cell_at(x, y);
  const int r = static_cast<int>(std::ceil(radius / map.resolution()));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const slam::CellIndex q{c.x + dx, c.y + dy};
      if (map.is_known(q) && map.probability(q) >= threshold) return true;
    }
  return false;
}

}  // namespace

MapQuality map_quality(const slam::OccupancyGrid& map, const World& world, const ReachableArea& area,
                       double occupied_threshold) {
  MapQuality q;
  // Tolerance: one map cell plus one world cell, so resolution differences do not count.
  const double tol = map.resolution() + world.resolution();
  std::size_t true_obstacles = 0, found_walls = 0;
  slam::CellIndex lo, hi;
  if (map.known_bounds(lo, hi)) {
    for (int y = lo.y; y <= hi.y; ++y) {
      for (int x = lo.x; x <= hi.x; ++x) {
        const slam::CellIndex c{x, y};
        if (!map.is_known(c) || map.probability(c) < occupied_threshold) continue;
        ++q.map_obstacles;
        double cx, cy;
        map.cell_center(c, cx, cy);
        const int r = std::max(1, static_cast<int>(std::ceil(tol / world.resolution())));
        if (world_obstacle_near(world, world.cell_of({cx, cy}), r)) ++true_obstacles;
      }
    }
  }
  const auto reachable = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < world.width() && y < world.height() &&
           area.reachable[static_cast<std::size_t>(y) * static_cast<std::size_t>(world.width()) +
                          static_cast<std::size_t>(x)];
  };
  for (int y = 0; y < world.height(); ++y) {
    for (int x = 0; x < world.width(); ++x) {
      if (!world.is_occupied(slam::CellIndex{x, y})) continue;
      if (!reachable(x + 1, y) && !reachable(x - 1, y) && !reachable(x, y + 1) && !reachable(x, y - 1)) continue;
      ++q.world_walls;
      const Eigen::Vector2d c = world.center_of({x, y});
      if (map_obstacle_near(map, c.x(), c.y(), tol, occupied_threshold)) ++found_walls;
    }
  }
  q.precision = q.map_obstacles ? static_cast<double>(true_obstacles) / static_cast<double>(q.map_obstacles) : 0.0;
  q.recall = q.world_walls ? static_cast<double>(found_walls) / static_cast<double>(q.world_walls) : 0.0;
  return q;
}

}  // namespace lookahead::exploration
