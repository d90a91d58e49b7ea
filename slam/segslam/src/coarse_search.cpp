// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/coarse_search.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "index_grid_search.hpp"

namespace lookahead::slam::segslam {
namespace {

using detail::GridHit;
using detail::IndexGrid;

// Points near an obstacle at level `level` with the robot at (x, y). At level 0 the score;
// above, an upper bound of the score over the block of translations that starts at (x, y).
int count_near(const NearField& f, std::size_t level, double x, double y, const Points2& rotated, double inv) {
  int near = 0;
  for (const auto& p : rotated)
    near += f.near(level, NearField::floor_int((x + p.x()) * inv), NearField::floor_int((y + p.y()) * inv));
  return near;
}

// The pose grid as indices (index_grid_search.hpp): the points rotated once per heading, the
// score or bound of an index, and the pose of the best.
struct Scorer {
  const NearField& field;
  const Pose2 centre;
  const double step, inv;  // [m], 1 / resolution
  const IndexGrid index;
  std::vector<Points2> rotated;  // by heading index a + na
  std::vector<double> headings;

  Scorer(const NearField& f, const Points2& points, const Pose2& c, const PoseGrid& grid)
      : field(f), centre(c), step(grid.step), inv(1.0 / f.resolution()), index(grid) {
    for (int a = -index.na; a <= index.na; ++a) {
      const double th = normalize_angle(c.theta + a * grid.angle_step), cs = std::cos(th), sn = std::sin(th);
      Points2 r(points.size());
      for (std::size_t k = 0; k < points.size(); ++k) {
        r[k] = {cs * points[k].x() - sn * points[k].y(), sn * points[k].x() + cs * points[k].y()};
      }
      rotated.push_back(std::move(r));
      headings.push_back(th);
    }
  }

  int operator()(std::size_t level, int a, int i, int j) const {
    return count_near(field, level, centre.x + i * step, centre.y + j * step, rotated[index.heading(a)], inv);
  }

  // The pose of the best index; the centre with no score if there is none.
  [[nodiscard]] CoarseResult result(const std::optional<GridHit>& hit) const {
    if (!hit) return {centre, -1};
    return {{centre.x + hit->i * step, centre.y + hit->j * step, headings[index.heading(hit->a)]}, hit->score};
  }
};

}  // namespace

std::vector<int> branch_and_bound_dilations(const PoseGrid& grid, double resolution) {
  const IndexGrid s(grid);
  const double inv = 1.0 / resolution;
  std::vector<int> out;
  // A block of L translations moves a point by (L - 1) step: that many cells, rounded up,
  // plus one for the floor of the block's first point (the bound must never be below).
  for (int length = 2; length <= detail::kTopBlock && length / 2 < s.per_axis(); length *= 2) {
    out.push_back(static_cast<int>(std::ceil((length - 1) * grid.step * inv)) + 2);
  }
  return out;
}

CoarseResult coarse_search_exhaustive(const NearField& field, const Points2& points, const Pose2& centre,
                                      const PoseGrid& grid) {
  const Scorer score(field, points, centre, grid);
  // Scores are counts, never below 0: the first index wins over the -1 of "none yet".
  return score.result(detail::exhaustive_search(score.index, score, -1));
}

CoarseResult coarse_search_branch_and_bound(const NearField& field, const Points2& points, const Pose2& centre,
                                            const PoseGrid& grid) {
  const std::size_t top = branch_and_bound_dilations(grid, field.resolution()).size();
  // A field built for a wider grid serves a narrower one: level l is the block of 2^l steps.
  if (field.levels() < top + 1) {
    throw std::invalid_argument("coarse_search_branch_and_bound: the near field has " + std::to_string(field.levels()) +
                                " levels, the pose grid needs " + std::to_string(top + 1));
  }
  const Scorer score(field, points, centre, grid);
  return score.result(detail::branch_and_bound(score.index, top, score, -1));
}

}  // namespace lookahead::slam::segslam
