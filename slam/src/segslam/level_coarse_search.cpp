// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/level_coarse_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lookahead::slam::segslam {
namespace {

// The largest block of translations per axis, as in 2D (coarse_search.cpp): wider blocks
// bound almost every point as near and cost more to build than they prune.
constexpr int kTopBlock = 8;

struct Shape {
  int n, na, m;  // half extents in steps, translations per axis (2n + 1)
  explicit Shape(const LevelPoseGrid& g)
      : n(static_cast<int>(g.radius / g.step)), na(static_cast<int>(g.angle / g.angle_step)), m(2 * n + 1) {}
  // Position in the exhaustive search's (yaw, x, y) order, for its tie-breaking.
  [[nodiscard]] long order(int a, int i, int j) const { return (static_cast<long>(a + na) * m + (i + n)) * m + (j + n); }
};

// A point turned by one yaw: the products of x' = (x + c px) - s py, y' = (y + s px) + c py
// (the order of Pose4's composition, so every key is the one the plain test computes), and
// its height key, which no pose of the grid changes.
struct Turned {
  double cx, sy, sx, cy;
  long kz;
};

struct Heading {
  double yaw;
  std::vector<Turned> points;
};

std::vector<Heading> headings_of(const NearOccupiedField& f, const Points3& points, const Pose4& guess,
                                 const LevelPoseGrid& g, const Shape& s) {
  std::vector<long> kz(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) kz[k] = f.axis_key(guess.z + points[k].z());
  std::vector<Heading> out;
  for (int a = -s.na; a <= s.na; ++a) {
    Heading h{normalize_angle(guess.yaw + a * g.angle_step), {}};
    const double c = std::cos(h.yaw), sn = std::sin(h.yaw);
    h.points.reserve(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Eigen::Vector3d& p = points[k];
      h.points.push_back({c * p.x(), sn * p.y(), sn * p.x(), c * p.y(), kz[k]});
    }
    out.push_back(std::move(h));
  }
  return out;
}

// Points near in the plane at bound level `level` with the robot at (x, y): at level 0 the
// score, above an upper bound of it over the block of translations starting at (x, y).
int count_near(const NearOccupiedField& f, std::size_t level, double x, double y, const Heading& h) {
  int near = 0;
  for (const Turned& t : h.points) {
    near += f.near_in_plane(level, f.axis_key((x + t.cx) - t.sy), f.axis_key((y + t.sx) + t.cy), t.kz) ? 1 : 0;
  }
  return near;
}

}  // namespace

std::vector<int> level_bound_widths(double step, double resolution) {
  std::vector<int> out;
  // A block of L translations moves a point by (L - 1) steps: that many voxels, rounded up,
  // plus one for the floor of the block's first point (the bound must never be below).
  for (int length = 2; length <= kTopBlock; length *= 2) {
    out.push_back(static_cast<int>(std::ceil((length - 1) * step / resolution)) + 2);
  }
  return out;
}

int near_in_plane_count(const NearOccupiedField& field, const Pose4& pose, const Points3& points) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  int near = 0;
  for (const auto& p : points) {
    const Eigen::Vector3d q(pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y(), pose.z + p.z());
    near += field.near_in_plane(q) ? 1 : 0;
  }
  return near;
}

LevelCoarseResult level_search_exhaustive(const NearOccupiedField& field, const Points3& points, const Pose4& guess,
                                          const LevelPoseGrid& grid) {
  const Shape s(grid);
  const std::vector<Heading> headings = headings_of(field, points, guess, grid, s);
  LevelCoarseResult best{guess, near_in_plane_count(field, guess, points)};
  for (int a = -s.na; a <= s.na; ++a) {
    const Heading& h = headings[static_cast<std::size_t>(a + s.na)];
    for (int i = -s.n; i <= s.n; ++i) {
      for (int j = -s.n; j <= s.n; ++j) {
        const double x = guess.x + i * grid.step, y = guess.y + j * grid.step;
        const int v = count_near(field, 0, x, y, h);
        if (v > best.score) best = {{x, y, guess.z, h.yaw}, v};
      }
    }
  }
  return best;
}

LevelCoarseResult level_search_branch_and_bound(const NearOccupiedField& field, const Points3& points,
                                                const Pose4& guess, const LevelPoseGrid& grid) {
  const std::vector<int> widths = level_bound_widths(grid.step, field.resolution());
  if (field.bound_widths() != widths) {
    throw std::invalid_argument("level_search_branch_and_bound: the field's bound levels do not fit a " +
                                std::to_string(grid.step) + " m grid");
  }
  const Shape s(grid);
  const std::vector<Heading> headings = headings_of(field, points, guess, grid, s);
  // A block: 2^level x 2^level translations from (i, j) at heading a; `bound` >= the score
  // of each, `order` <= the order of each (exact at level 0).
  struct Block {
    std::size_t level;
    int a, i, j, bound;
    long order;
  };
  const auto block = [&](std::size_t level, int a, int i, int j) {
    const int b = count_near(field, level, guess.x + i * grid.step, guess.y + j * grid.step,
                             headings[static_cast<std::size_t>(a + s.na)]);
    return Block{level, a, i, j, b, s.order(a, i, j)};
  };
  // Most promising first; equal bounds in the exhaustive order, so ties resolve as there.
  const auto first = [](const Block& x, const Block& y) { return x.bound > y.bound || (x.bound == y.bound && x.order < y.order); };
  std::vector<Block> stack, children;
  const auto push_sorted = [&](std::vector<Block>& blocks) {
    std::sort(blocks.begin(), blocks.end(), first);
    stack.insert(stack.end(), blocks.rbegin(), blocks.rend());
  };
  const std::size_t top = widths.size();
  const int side = 1 << top;
  for (int a = -s.na; a <= s.na; ++a) {
    for (int i = -s.n; i <= s.n; i += side) {
      for (int j = -s.n; j <= s.n; j += side) children.push_back(block(top, a, i, j));
    }
  }
  push_sorted(children);
  // The guess holds until a pose scores more (order -1: no tie replaces it).
  LevelCoarseResult best{guess, near_in_plane_count(field, guess, points)};
  long best_order = -1;
  while (!stack.empty()) {
    const Block b = stack.back();
    stack.pop_back();
    if (b.bound < best.score || (b.bound == best.score && b.order > best_order)) continue;
    if (b.level == 0) {
      best = {{guess.x + b.i * grid.step, guess.y + b.j * grid.step, guess.z, headings[static_cast<std::size_t>(b.a + s.na)].yaw}, b.bound};
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
