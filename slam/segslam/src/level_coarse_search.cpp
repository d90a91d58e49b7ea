// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/level_coarse_search.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "index_grid_search.hpp"

namespace lookahead::slam::segslam {
namespace {

using detail::GridHit;
using detail::IndexGrid;

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
                                 const LevelPoseGrid& g, const IndexGrid& s) {
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

// The level pose grid as indices (index_grid_search.hpp): the points turned once per yaw, the
// score or bound of an index, and the pose of the best. The guess holds until a pose scores
// more than it.
struct Scorer {
  const NearOccupiedField& field;
  const Pose4 guess;
  const double step;  // [m]
  const IndexGrid index;
  const std::vector<Heading> headings;  // by yaw index a + na
  const int guess_score;

  Scorer(const NearOccupiedField& f, const Points3& points, const Pose4& g, const LevelPoseGrid& grid)
      : field(f),
        guess(g),
        step(grid.step),
        index(grid),
        headings(headings_of(f, points, g, grid, index)),
        guess_score(near_in_plane_count(f, g, points)) {}

  int operator()(std::size_t level, int a, int i, int j) const {
    return count_near(field, level, guess.x + i * step, guess.y + j * step, headings[index.heading(a)]);
  }

  [[nodiscard]] LevelCoarseResult result(const std::optional<GridHit>& hit) const {
    if (!hit) return {guess, guess_score};
    const double yaw = headings[index.heading(hit->a)].yaw;
    return {{guess.x + hit->i * step, guess.y + hit->j * step, guess.z, yaw}, hit->score};
  }
};

// The scores and bounds of one level_search_peaks call, kept across its passes: each pass
// is a full branch and bound whose blocks' bounds are the same (only the level-0 scores of
// poses near an earlier peak change, and those are applied on top), and the later passes
// revisit the blocks of the earlier ones. Why: the wide re-entry search (wide_reentry.hpp)
// finds 4 peaks over +-25 m / +-1 rad, and scoring its blocks was most of its time (28 % of
// a 5-particle garage run's samples in count_near). A block of level L starts at an index i
// with (i + n) a multiple of 2^L (the top blocks start at -n in steps of 2^top, and each
// splits into halves), so (i + n) >> L numbers them. -1: not scored yet.
class BoundMemo {
 public:
  BoundMemo(const IndexGrid& g, std::size_t top) : g_(g) {
    std::size_t offset = 0;
    for (std::size_t level = 0; level <= top; ++level) {
      const auto side = static_cast<std::size_t>(((g.per_axis() - 1) >> level) + 1);
      offsets_.push_back(offset);
      sides_.push_back(side);
      offset += side * side * static_cast<std::size_t>(2 * g.na + 1);
    }
    values_.assign(offset, -1);
  }

  int& at(std::size_t level, int a, int i, int j) {
    const std::size_t side = sides_[level];
    const auto row = static_cast<std::size_t>((i + g_.n) >> level);
    const auto column = static_cast<std::size_t>((j + g_.n) >> level);
    return values_[offsets_[level] + (g_.heading(a) * side + row) * side + column];
  }

 private:
  IndexGrid g_;
  std::vector<std::size_t> offsets_, sides_;
  std::vector<int> values_;
};

}  // namespace

std::vector<int> level_bound_widths(double step, double resolution) {
  std::vector<int> out;
  // A block of L translations moves a point by (L - 1) steps: that many voxels, rounded up,
  // plus one for the floor of the block's first point (the bound must never be below).
  for (int length = 2; length <= detail::kTopBlock; length *= 2) {
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
  const Scorer score(field, points, guess, grid);
  return score.result(detail::exhaustive_search(score.index, score, score.guess_score));
}

LevelCoarseResult level_search_branch_and_bound(const NearOccupiedField& field, const Points3& points,
                                                const Pose4& guess, const LevelPoseGrid& grid) {
  const std::vector<int> widths = level_bound_widths(grid.step, field.resolution());
  if (field.bound_widths() != widths) {
    throw std::invalid_argument("level_search_branch_and_bound: the field's bound levels do not fit a " +
                                std::to_string(grid.step) + " m grid");
  }
  const Scorer score(field, points, guess, grid);
  return score.result(detail::branch_and_bound(score.index, widths.size(), score, score.guess_score));
}

std::vector<LevelCoarseResult> level_search_peaks(const NearOccupiedField& field, const Points3& points,
                                                  const Pose4& guess, const LevelPoseGrid& grid, std::size_t count,
                                                  double separation, double angle_separation) {
  return level_search_peaks_within(field, points, guess, grid, {{guess, grid.radius, grid.angle}}, count, separation,
                                   angle_separation)
      .front();
}

namespace {

// The indices of a part of the grid (clipped to the grid).
struct IndexBox {
  int a0, a1, i0, i1, j0, j1;

  // Does the block of 2^level translations from (i, j) at heading a meet the box?
  [[nodiscard]] bool meets(std::size_t level, int a, int i, int j) const {
    const int last = (1 << level) - 1;
    return a >= a0 && a <= a1 && i <= i1 && i + last >= i0 && j <= j1 && j + last >= j0;
  }
};

IndexBox index_box(const IndexGrid& g, const Pose4& guess, const LevelPoseGrid& grid, const LevelSubgrid& part) {
  constexpr double kSlack = 1e-9;  // a pose on the part's edge belongs to it
  const auto from = [](double v) { return static_cast<int>(std::ceil(v - kSlack)); };
  const auto to = [](double v) { return static_cast<int>(std::floor(v + kSlack)); };
  const double dx = part.centre.x - guess.x, dy = part.centre.y - guess.y;
  const double dyaw = normalize_angle(part.centre.yaw - guess.yaw);
  return {std::max(-g.na, from((dyaw - part.angle) / grid.angle_step)),
          std::min(g.na, to((dyaw + part.angle) / grid.angle_step)),
          std::max(-g.n, from((dx - part.radius) / grid.step)),
          std::min(g.n, to((dx + part.radius) / grid.step)),
          std::max(-g.n, from((dy - part.radius) / grid.step)),
          std::min(g.n, to((dy + part.radius) / grid.step))};
}

}  // namespace

std::vector<std::vector<LevelCoarseResult>> level_search_peaks_within(
    const NearOccupiedField& field, const Points3& points, const Pose4& guess, const LevelPoseGrid& grid,
    const std::vector<LevelSubgrid>& parts, std::size_t count, double separation, double angle_separation) {
  const std::vector<int> widths = level_bound_widths(grid.step, field.resolution());
  if (field.bound_widths() != widths) {
    throw std::invalid_argument("level_search_peaks: the field's bound levels do not fit a " +
                                std::to_string(grid.step) + " m grid");
  }
  const Scorer score(field, points, guess, grid);
  BoundMemo memo(score.index, widths.size());
  std::vector<std::vector<LevelCoarseResult>> out;
  for (const LevelSubgrid& part : parts) {
    const IndexBox box = index_box(score.index, guess, grid, part);
    std::vector<detail::GridHit> found;
    // A grid pose near an earlier peak scores 0 at level 0; a block's bound is left as it is
    // (still never below the score of any pose in it). Outside the part, everything is 0.
    const auto excluded = [&](int a, int i, int j) {
      for (const detail::GridHit& h : found) {
        const double dyaw = std::abs(a - h.a) * grid.angle_step;
        if (std::hypot(i - h.i, j - h.j) * grid.step <= separation && dyaw <= angle_separation) return true;
      }
      return false;
    };
    const auto bound = [&](std::size_t level, int a, int i, int j) {
      if (!box.meets(level, a, i, j) || (level == 0 && excluded(a, i, j))) return 0;
      int& v = memo.at(level, a, i, j);
      if (v < 0) v = score(level, a, i, j);
      return v;
    };
    std::vector<LevelCoarseResult> peaks;
    while (peaks.size() < count) {
      const std::optional<GridHit> hit = detail::branch_and_bound(score.index, widths.size(), bound, 0);
      if (!hit) break;
      found.push_back(*hit);
      peaks.push_back(score.result(hit));
    }
    out.push_back(std::move(peaks));
  }
  return out;
}

LevelSubgrid covering_subgrid(const LevelSubgrid& first, const std::vector<LevelSubgrid>& parts) {
  LevelSubgrid out{first.centre, first.radius, first.angle};
  for (const LevelSubgrid& r : parts) {
    const double offset = std::max(std::abs(r.centre.x - first.centre.x), std::abs(r.centre.y - first.centre.y));
    out.radius = std::max(out.radius, offset + r.radius);
    out.angle = std::max(out.angle, std::abs(normalize_angle(r.centre.yaw - first.centre.yaw)) + r.angle);
  }
  out.angle = std::min(out.angle, M_PI);
  return out;
}

}  // namespace lookahead::slam::segslam
