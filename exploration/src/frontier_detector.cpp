// SPDX-License-Identifier: MIT
#include "lookahead/exploration/frontier_detector.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <iterator>
#include <stdexcept>

namespace lookahead::exploration {

using slam::CellIndex;

namespace {
// Undecided cells this many cells (Chebyshev) from never-seen space belong to the edge of the
// seen region: the band a single grazing beam leaves is one or two cells wide.
constexpr int kUndecidedBand = 2;

const FrontierOptions& checked(const FrontierOptions& options) {
  if (!(options.free_threshold > 0 && options.free_threshold < 0.5) ||
      !(options.occupied_threshold > 0.5 && options.occupied_threshold < 1) || options.min_cluster_cells < 1 ||
      options.robot_radius < 0 || options.goal_search_radius < 0 || options.cluster_gap < 1 ||
      options.cluster_gap > 5) {
    throw std::invalid_argument("frontier options out of range");
  }
  return options;
}
}  // namespace

// Frontier cells as the mission needs them: undecided cells at the edge of the seen region
// count as unexplored, and the unseen inside of a wall is no frontier.
FrontierDetector::FrontierDetector(const FrontierOptions& options)
    : options_(checked(options)),
      cell_test_(slam::FrontierCellRule{options.free_threshold, options.occupied_threshold, kUndecidedBand, true}) {}

bool FrontierDetector::is_free(const slam::OccupancyGrid& grid, CellIndex c) const {
  return cell_test_.is_free(grid, c);
}

bool FrontierDetector::is_occupied(const slam::OccupancyGrid& grid, CellIndex c) const {
  return cell_test_.is_occupied(grid, c);
}

bool FrontierDetector::is_frontier(const slam::OccupancyGrid& grid, CellIndex c) const {
  return cell_test_.is_frontier(grid, c);
}

void FrontierDetector::update(const slam::OccupancyGrid& grid, CellIndex min, CellIndex max) {
  // A cell's state depends on its 4-neighbours, so the border of the region may change too.
  const CellIndex lo{min.x - 1, min.y - 1}, hi{max.x + 1, max.y + 1};
  // The frontier is a few thousand cells, the region a few hundred thousand: dropping the
  // frontier cells inside it costs less than asking the set about every cell.
  for (auto it = cells_.begin(); it != cells_.end();) {
    const bool inside = it->x >= lo.x && it->x <= hi.x && it->y >= lo.y && it->y <= hi.y;
    it = inside ? cells_.erase(it) : std::next(it);
  }
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const CellIndex c{x, y};
      if (is_frontier(grid, c) && !retired_.count(c)) cells_.insert(c);
    }
  }
}

std::size_t FrontierDetector::retire_near(const slam::OccupancyGrid& grid, double x, double y, double radius) {
  std::vector<CellIndex> gone;
  for (const CellIndex c : cells_) {
    double cx, cy;
    grid.cell_center(c, cx, cy);
    if (std::hypot(cx - x, cy - y) <= radius) gone.push_back(c);
  }
  for (const CellIndex c : gone) {
    cells_.erase(c);
    retired_.insert(c);
  }
  return gone.size();
}

void FrontierDetector::rebuild(const slam::OccupancyGrid& grid) {
  cells_.clear();
  CellIndex lo, hi;
  if (grid.known_bounds(lo, hi)) update(grid, lo, hi);
}

bool FrontierDetector::has_clearance(const slam::OccupancyGrid& grid, CellIndex c) const {
  const int r = static_cast<int>(std::ceil(options_.robot_radius / grid.resolution()));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      if (dx * dx + dy * dy > r * r) continue;
      if (is_occupied(grid, {c.x + dx, c.y + dy})) return false;
    }
  }
  return true;
}

// The goal is the free cell with clearance closest to the cluster's centroid, searched
// among the cluster's cells and then breadth-first through free space around them: a
// centroid can lie inside a wall or in unknown space, a goal must not.
bool FrontierDetector::find_goal(const slam::OccupancyGrid& grid, FrontierCluster& cluster) const {
  const int max_steps = static_cast<int>(std::ceil(options_.goal_search_radius / grid.resolution()));
  std::unordered_set<CellIndex, CellHash> seen(cluster.cells.begin(), cluster.cells.end());
  std::deque<std::pair<CellIndex, int>> queue;
  for (const CellIndex c : cluster.cells) queue.push_back({c, 0});
  double best = INFINITY;
  while (!queue.empty()) {
    const auto [c, depth] = queue.front();
    queue.pop_front();
    if (has_clearance(grid, c)) {
      double x, y;
      grid.cell_center(c, x, y);
      const double d = std::hypot(x - cluster.centroid_x, y - cluster.centroid_y);
      if (d < best) {
        best = d;
        cluster.goal_x = x;
        cluster.goal_y = y;
      }
    }
    if (depth >= max_steps || best < INFINITY) continue;  // stop widening once a goal exists
    for (const CellIndex n :
         {CellIndex{c.x + 1, c.y}, CellIndex{c.x - 1, c.y}, CellIndex{c.x, c.y + 1}, CellIndex{c.x, c.y - 1}}) {
      if (is_free(grid, n) && seen.insert(n).second) queue.push_back({n, depth + 1});
    }
  }
  cluster.has_goal = best < INFINITY;
  return cluster.has_goal;
}

std::vector<FrontierCluster> FrontierDetector::clusters(const slam::OccupancyGrid& grid) const {
  std::vector<FrontierCluster> out;
  std::unordered_set<CellIndex, CellHash> visited;
  // Sorted seeds make the cluster order (and so every later tie) independent of hashing.
  std::vector<CellIndex> seeds(cells_.begin(), cells_.end());
  std::sort(seeds.begin(), seeds.end(), [](CellIndex a, CellIndex b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  for (const CellIndex seed : seeds) {
    if (!visited.insert(seed).second) continue;
    FrontierCluster cluster;
    std::deque<CellIndex> queue{seed};
    while (!queue.empty()) {
      const CellIndex c = queue.front();
      queue.pop_front();
      cluster.cells.push_back(c);
      const int g = options_.cluster_gap;
      for (int dy = -g; dy <= g; ++dy) {
        for (int dx = -g; dx <= g; ++dx) {
          const CellIndex n{c.x + dx, c.y + dy};
          if (cells_.count(n) && visited.insert(n).second) queue.push_back(n);
        }
      }
    }
    if (static_cast<int>(cluster.cells.size()) < options_.min_cluster_cells) continue;
    for (const CellIndex c : cluster.cells) {
      double x, y;
      grid.cell_center(c, x, y);
      cluster.centroid_x += x / static_cast<double>(cluster.cells.size());
      cluster.centroid_y += y / static_cast<double>(cluster.cells.size());
    }
    find_goal(grid, cluster);
    out.push_back(std::move(cluster));
  }
  return out;
}

}  // namespace lookahead::exploration
