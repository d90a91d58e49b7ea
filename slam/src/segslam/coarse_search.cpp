// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/coarse_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lookahead::slam::segslam {
namespace {

struct Shape {
  int n, na, m;  // half extents in steps, translations per axis (2n + 1)
  double inv;    // 1 / resolution
  Shape(const PoseGrid& g, double resolution)
      : n(static_cast<int>(g.radius / g.step)), na(static_cast<int>(g.angle / g.angle_step)), m(2 * n + 1),
        inv(1.0 / resolution) {}
  // Position in the exhaustive search's (angle, x, y) order, for its tie-breaking.
  [[nodiscard]] long order(int a, int i, int j) const {
    return (static_cast<long>(a + na) * m + (i + n)) * m + (j + n);
  }
};

// The points rotated by each of the grid's headings (index a + na).
std::vector<Points2> rotations(const Points2& points, const Pose2& centre, const PoseGrid& g, const Shape& s,
                               std::vector<double>& headings) {
  std::vector<Points2> out;
  for (int a = -s.na; a <= s.na; ++a) {
    const double th = normalize_angle(centre.theta + a * g.angle_step), c = std::cos(th), sn = std::sin(th);
    Points2 r(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      r[k] = {c * points[k].x() - sn * points[k].y(), sn * points[k].x() + c * points[k].y()};
    }
    out.push_back(std::move(r));
    headings.push_back(th);
  }
  return out;
}

// Points near an obstacle at level `level` with the robot at (x, y). At level 0 the score;
// above, an upper bound of the score over the block of translations that starts at (x, y).
int count_near(const NearField& f, std::size_t level, double x, double y, const Points2& rotated, double inv) {
  int near = 0;
  for (const auto& p : rotated) near += f.near(level, NearField::floor_int((x + p.x()) * inv), NearField::floor_int((y + p.y()) * inv));
  return near;
}

// The largest block of translations per axis: wider blocks bound almost every point as near
// (their boxes span metres) and their levels cost more to build than they prune.
constexpr int kTopBlock = 8;

}  // namespace

std::vector<int> branch_and_bound_dilations(const PoseGrid& grid, double resolution) {
  const Shape s(grid, resolution);
  std::vector<int> out;
  // A block of L translations moves a point by (L - 1) step: that many cells, rounded up,
  // plus one for the floor of the block's first point (the bound must never be below).
  for (int length = 2; length <= kTopBlock && length / 2 < s.m; length *= 2) {
    out.push_back(static_cast<int>(std::ceil((length - 1) * grid.step * s.inv)) + 2);
  }
  return out;
}

CoarseResult coarse_search_exhaustive(const NearField& field, const Points2& points, const Pose2& centre,
                                      const PoseGrid& grid) {
  const Shape s(grid, field.resolution());
  std::vector<double> headings;
  const std::vector<Points2> rotated = rotations(points, centre, grid, s, headings);
  CoarseResult best{centre, -1};
  for (int a = -s.na; a <= s.na; ++a) {
    for (int i = -s.n; i <= s.n; ++i) {
      for (int j = -s.n; j <= s.n; ++j) {
        const double x = centre.x + i * grid.step, y = centre.y + j * grid.step;
        const int v = count_near(field, 0, x, y, rotated[static_cast<std::size_t>(a + s.na)], s.inv);
        if (v > best.score) best = {{x, y, headings[static_cast<std::size_t>(a + s.na)]}, v};
      }
    }
  }
  return best;
}

CoarseResult coarse_search_branch_and_bound(const NearField& field, const Points2& points, const Pose2& centre,
                                            const PoseGrid& grid) {
  const Shape s(grid, field.resolution());
  const std::size_t top = branch_and_bound_dilations(grid, field.resolution()).size();
  if (field.levels() != top + 1) {
    throw std::invalid_argument("coarse_search_branch_and_bound: the near field has " + std::to_string(field.levels()) +
                                " levels, the pose grid needs " + std::to_string(top + 1));
  }
  std::vector<double> headings;
  const std::vector<Points2> rotated = rotations(points, centre, grid, s, headings);
  // A block: 2^level x 2^level translations from (i, j) at heading a; `bound` >= the score
  // of each, `order` <= the order of each (exact at level 0).
  struct Block {
    std::size_t level;
    int a, i, j, bound;
    long order;
  };
  const auto block = [&](std::size_t level, int a, int i, int j) {
    const int b = count_near(field, level, centre.x + i * grid.step, centre.y + j * grid.step,
                             rotated[static_cast<std::size_t>(a + s.na)], s.inv);
    return Block{level, a, i, j, b, s.order(a, i, j)};
  };
  // Most promising first; equal bounds in the exhaustive order, so ties resolve as there.
  const auto first = [](const Block& x, const Block& y) { return x.bound > y.bound || (x.bound == y.bound && x.order < y.order); };
  std::vector<Block> stack;
  const auto push_sorted = [&](std::vector<Block>& blocks) {
    std::sort(blocks.begin(), blocks.end(), first);
    stack.insert(stack.end(), blocks.rbegin(), blocks.rend());
  };
  std::vector<Block> roots;
  const int side = 1 << top;
  for (int a = -s.na; a <= s.na; ++a) {
    for (int i = -s.n; i <= s.n; i += side) {
      for (int j = -s.n; j <= s.n; j += side) roots.push_back(block(top, a, i, j));
    }
  }
  push_sorted(roots);
  CoarseResult best{centre, -1};
  long best_order = std::numeric_limits<long>::max();
  std::vector<Block> children;
  while (!stack.empty()) {
    const Block b = stack.back();
    stack.pop_back();
    if (b.bound < best.score || (b.bound == best.score && b.order > best_order)) continue;
    if (b.level == 0) {
      best = {{centre.x + b.i * grid.step, centre.y + b.j * grid.step, headings[static_cast<std::size_t>(b.a + s.na)]}, b.bound};
      best_order = b.order;
      continue;
    }
    const int half = 1 << (b.level - 1);
    children.clear();
    for (int di : {0, half}) {
      for (int dj : {0, half}) {
        if (b.i + di > s.n || b.j + dj > s.n) continue;
        children.push_back(block(b.level - 1, b.a, b.i + di, b.j + dj));
      }
    }
    push_sorted(children);
  }
  return best;
}

}  // namespace lookahead::slam::segslam
