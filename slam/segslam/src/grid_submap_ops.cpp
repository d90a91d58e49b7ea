// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/grid_submap_ops.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "lookahead/slam/grid/grid_tile.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

PreparedScan as_scan(const Points2& cloud) {
  PreparedScan s;  // laser offset identity: the points are in the robot frame already
  for (const auto& p : cloud) {
    s.x.push_back(static_cast<float>(p.x()));
    s.y.push_back(static_cast<float>(p.y()));
  }
  return s;
}

// Every obstacle cell of `map`, as a point in the map's frame.
Points2 obstacle_points(const OccupancyGrid& map) {
  Points2 out;
  CellIndex lo, hi;
  if (!map.known_bounds(lo, hi)) return out;
  for (int ty = lo.y >> GridTile::kBits; ty <= hi.y >> GridTile::kBits; ++ty) {
    for (int tx = lo.x >> GridTile::kBits; tx <= hi.x >> GridTile::kBits; ++tx) {
      const GridTile* t = map.tile(tx, ty);
      if (!t) continue;
      for (int i = 0; i < GridTile::kCells; ++i) {
        if (!(t->flags[static_cast<std::size_t>(i)] & GridTile::kObstacle)) continue;
        double cx, cy;
        map.cell_center(
            {GridTile::first_cell(tx) + (i & (GridTile::kSide - 1)), GridTile::first_cell(ty) + (i >> GridTile::kBits)},
            cx, cy);
        out.emplace_back(cx, cy);
      }
    }
  }
  return out;
}

// likelihood.hit_ratio's count of hits (end points within its hit distance of an obstacle)
// read from the candidate's hit field: the same cells (cell_at divides), bits for tiles.
int hit_count(const NearField& hits, const Pose2& robot, const PreparedScan& scan) {
  const double c = std::cos(robot.theta), s = std::sin(robot.theta), res = hits.resolution();
  int n = 0;
  for (std::size_t i = 0; i < scan.x.size(); ++i) {
    n += hits.near(0, NearField::floor_int((robot.x + c * scan.x[i] - s * scan.y[i]) / res),
                   NearField::floor_int((robot.y + s * scan.x[i] + c * scan.y[i]) / res));
  }
  return n;
}

// Exhaustive search of a pose grid around `centre` for the best score.
template <typename Score>
Pose2 grid_search(const Pose2& centre, double radius, double step, double angle, double angle_step, Score&& score) {
  const int n = static_cast<int>(radius / step), na = static_cast<int>(angle / angle_step);
  Pose2 best = centre;
  auto best_score = score(centre);
  for (int a = -na; a <= na; ++a) {
    for (int i = -n; i <= n; ++i) {
      for (int j = -n; j <= n; ++j) {
        const Pose2 p{centre.x + i * step, centre.y + j * step, normalize_angle(centre.theta + a * angle_step)};
        const auto v = score(p);
        if (v > best_score) best_score = v, best = p;
      }
    }
  }
  return best;
}

// The pose near `guess` where most window points land on the candidate's obstacles: a coarse
// grid on a thinned cloud scored by the wide near-obstacle share (branch and bound, the same
// optimum as trying every pose), then a fine grid scored by hits within the sensor model's
// hit distance.
Pose2 coarse_search(const OccupancyGrid& map, const GridMatchTarget& target, const Points2& cloud, const Pose2& guess,
                    const MatchingOptions& o) {
  Points2 thin;
  const std::size_t every = std::max<std::size_t>(1, cloud.size() / 60);
  for (std::size_t i = 0; i < cloud.size(); i += every) thin.push_back(cloud[i]);
  const PoseGrid grid = coarse_pose_grid(map, o);
  const Pose2 coarse = coarse_search_branch_and_bound(target.near, thin, guess, grid).pose;
  const PreparedScan scan = as_scan(cloud);
  // Half the coarse step around its best pose, on a grid ICP converges from (5 x 5 x 5).
  return grid_search(coarse, grid.step / 2, grid.step / 4, 0.025, 0.0125,
                     [&](const Pose2& p) { return hit_count(target.hits, p, scan); });
}

}  // namespace

double predictive_score(const OccupancyGrid& map, const Pose2& pose, const LookaheadWindow& w,
                        const LikelihoodFieldModel& likelihood) {
  if (w.scans.empty()) return -1.0;
  double sum = 0;
  for (std::size_t i = 0; i < w.scans.size(); ++i) {
    sum += likelihood.hit_ratio(map, pose.compose(w.relative_poses[i]), w.scans[i]);
  }
  return sum / static_cast<double>(w.scans.size());
}

bool has_observed_near(const OccupancyGrid& map, double x, double y, double radius) {
  const double step = std::max(map.resolution(), radius / 4);
  for (double dx = -radius; dx <= radius; dx += step) {
    for (double dy = -radius; dy <= radius; dy += step) {
      if (map.is_known(map.cell_at(x + dx, y + dy))) return true;
    }
  }
  return false;
}

IcpTarget icp_target_of(const OccupancyGrid& map, const MatchingOptions& o) {
  return IcpTarget(bin_points(obstacle_points(map), o.bin_size), {o.icp_iterations, o.icp_max_distance, o.bin_size});
}

PoseGrid coarse_pose_grid(const OccupancyGrid& map, const MatchingOptions& o) {
  // The near-obstacle share is flat within the field radius: steps of most of it miss no peak.
  const double step = std::max(0.8 * map.distance_radius_cells() * map.resolution(), o.bin_size);
  return {o.search_radius, step, o.search_angle, 0.05};
}

GridMatchTarget match_target_of(const OccupancyGrid& map, const MatchingOptions& o,
                                const LikelihoodFieldModel& likelihood) {
  return {NearField(map, GridTile::kFar - 1, branch_and_bound_dilations(coarse_pose_grid(map, o), map.resolution())),
          NearField(map, likelihood.hit_dist2()), icp_target_of(map, o)};
}

WindowMatch match_window(const OccupancyGrid& candidate, const GridMatchTarget& target, const LookaheadWindow& window,
                         const Pose2& guess, const MatchingOptions& o) {
  WindowMatch m;
  if (target.icp.size() < 10 || window.cloud.size() < 10) return m;
  const Pose2 seed = coarse_search(candidate, target, window.cloud, guess, o);
  const IcpResult icp = icp_binned(window.cloud, target.icp, seed, {o.icp_iterations, o.icp_max_distance, o.bin_size});
  m.pose = icp.transform;
  m.icp_error = icp.mean_error;
  m.translation = std::hypot(m.pose.x - guess.x, m.pose.y - guess.y);
  m.ok = icp.inlier_ratio >= o.min_inlier_ratio;
  m.weight = m.ok ? match_weight(m.icp_error, m.translation, o) : 0.0;
  return m;
}

void add_child_evidence(OccupancyGrid& into, const OccupancyGrid& child) {
  CellIndex lo, hi;
  if (!child.known_bounds(lo, hi)) return;
  for (int ty = lo.y >> GridTile::kBits; ty <= hi.y >> GridTile::kBits; ++ty) {
    for (int tx = lo.x >> GridTile::kBits; tx <= hi.x >> GridTile::kBits; ++tx) {
      const GridTile* t = child.tile(tx, ty);
      if (!t || t == into.tile(tx, ty)) continue;  // an untouched tile is the parent's own
      for (int i = 0; i < GridTile::kCells; ++i) {
        const int l = t->log_odds[static_cast<std::size_t>(i)];
        if (l == GridTile::kUnknown) continue;
        const CellIndex cell{GridTile::first_cell(tx) + (i & (GridTile::kSide - 1)),
                             GridTile::first_cell(ty) + (i >> GridTile::kBits)};
        if (into.is_known(cell)) continue;
        into.add_log_odds(cell, l);
      }
    }
  }
}

void MapCanvas::paste(const OccupancyGrid& map, const Pose2& frame, const OccupancyGrid* parent) {
  CellIndex lo, hi;
  if (!map.known_bounds(lo, hi)) return;
  const double scale = 1.0 / GridTile::kLogOddsScale;
  const double c = std::cos(frame.theta), s = std::sin(frame.theta);
  // Rotated cells alias: average the cells of this submap that land in one target cell, so
  // the pasted evidence is not doubled (the sum across submaps is the independence model).
  std::unordered_map<std::int64_t, std::pair<double, int>> mine;
  const auto key = [](int x, int y) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
                                     static_cast<std::uint32_t>(y));
  };
  for (int ty = lo.y >> GridTile::kBits; ty <= hi.y >> GridTile::kBits; ++ty) {
    for (int tx = lo.x >> GridTile::kBits; tx <= hi.x >> GridTile::kBits; ++tx) {
      const GridTile* t = map.tile(tx, ty);
      if (!t) continue;
      const GridTile* shared = parent ? parent->tile(tx, ty) : nullptr;
      if (shared == t) continue;  // copy-on-write: an untouched tile is the parent's evidence
      for (int i = 0; i < GridTile::kCells; ++i) {
        const auto l = t->log_odds[static_cast<std::size_t>(i)];
        if (l == GridTile::kUnknown) continue;
        const auto pl = shared ? shared->log_odds[static_cast<std::size_t>(i)] : GridTile::kUnknown;
        const double delta = (l - (pl == GridTile::kUnknown ? 0 : pl)) * scale;
        const CellIndex cell{GridTile::first_cell(tx) + (i & (GridTile::kSide - 1)),
                             GridTile::first_cell(ty) + (i >> GridTile::kBits)};
        double x, y;
        map.cell_center(cell, x, y);
        const double wx = frame.x + c * x - s * y, wy = frame.y + s * x + c * y;
        auto& [sum, n] =
            mine[key(static_cast<int>(std::floor(wx / resolution_)), static_cast<int>(std::floor(wy / resolution_)))];
        sum += delta;
        ++n;
      }
    }
  }
  for (const auto& [k, sn] : mine) {
    cells_.push_back({{static_cast<int>(k >> 32), static_cast<int>(static_cast<std::uint32_t>(k & 0xffffffff))},
                      sn.first / sn.second});
  }
}

ProbabilityMap MapCanvas::to_probability_map() const {
  ProbabilityMap m;
  m.resolution = resolution_;
  if (cells_.empty()) return m;
  int x0 = cells_[0].first.x, x1 = x0, y0 = cells_[0].first.y, y1 = y0;
  for (const auto& [c, l] : cells_) {
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  }
  m.width = x1 - x0 + 1;
  m.height = y1 - y0 + 1;
  m.origin_x = x0 * resolution_;
  m.origin_y = y0 * resolution_;
  const std::size_t n = static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height);
  std::vector<double> sum(n, 0.0);
  std::vector<char> known(n, 0);
  for (const auto& [c, l] : cells_) {
    const auto i = static_cast<std::size_t>((c.y - y0) * m.width + (c.x - x0));
    sum[i] += l;
    known[i] = 1;
  }
  m.p.assign(n, -1.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (known[i]) m.p[i] = 1.0 - 1.0 / (1.0 + std::exp(std::clamp(sum[i], min_, max_)));
  }
  return m;
}

}  // namespace lookahead::slam::segslam
