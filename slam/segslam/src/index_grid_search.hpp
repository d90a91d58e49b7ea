// SPDX-License-Identifier: MIT
// The search both coarse searches share (coarse_search.cpp in 2D, level_coarse_search.cpp in
// 3D): over the grid of indices (heading a, translation i, j) around a guess, the index with
// the highest score, ties to the first in (a, i, j) order. Exhaustively, or by branch and
// bound over blocks of 2^level x 2^level translations at one heading. What a score is and how
// an index becomes a pose stay with the callers; they hand in one callable,
// bound(level, a, i, j): at level 0 the score of index (a, i, j), above it a value never below
// the score of any index of the block of translations that starts at (i, j). Internal to
// segslam.
#pragma once

#include <algorithm>
#include <cstddef>
#include <optional>
#include <vector>

namespace lookahead::slam::segslam::detail {

/// The largest block of translations per axis: wider blocks bound almost every point as near
/// (their boxes span metres) and their levels cost more to build than they prune.
constexpr int kTopBlock = 8;

/// Headings a in [-na, na], translations i, j in [-n, n] per axis.
struct IndexGrid {
  int n, na;

  /// The indices of a pose grid (PoseGrid, LevelPoseGrid): radius / step, angle / angle_step.
  template <typename PoseGridT>
  explicit IndexGrid(const PoseGridT& g)
      : n(static_cast<int>(g.radius / g.step)), na(static_cast<int>(g.angle / g.angle_step)) {}

  [[nodiscard]] int per_axis() const { return 2 * n + 1; }
  [[nodiscard]] std::size_t heading(int a) const { return static_cast<std::size_t>(a + na); }
  /// Position in the exhaustive (a, i, j) order, for its tie-breaking.
  [[nodiscard]] long order(int a, int i, int j) const {
    const int m = per_axis();
    return (static_cast<long>(a + na) * m + (i + n)) * m + (j + n);
  }
};

/// An index of the grid and its score.
struct GridHit {
  int a, i, j, score;
};

/// Every index; the best one scoring more than `to_beat` (the guess's score, say), nothing
/// if none does.
template <typename Bound>
std::optional<GridHit> exhaustive_search(const IndexGrid& g, const Bound& bound, int to_beat) {
  std::optional<GridHit> best;
  for (int a = -g.na; a <= g.na; ++a) {
    for (int i = -g.n; i <= g.n; ++i) {
      for (int j = -g.n; j <= g.n; ++j) {
        const int v = bound(std::size_t{0}, a, i, j);
        if (v > to_beat) {
          to_beat = v;
          best = GridHit{a, i, j, v};
        }
      }
    }
  }
  return best;
}

namespace bnb {

// 2^level x 2^level translations from (i, j) at heading a; `bound` >= the score of each,
// `order` <= the order of each (exact at level 0).
struct Block {
  std::size_t level;
  int a, i, j, bound;
  long order;
};

// Onto the stack so that the most promising is popped first; equal bounds in the exhaustive
// order, so ties resolve as there (every block pushed together has its own order).
inline void push_sorted(std::vector<Block>& blocks, std::vector<Block>& stack) {
  std::sort(blocks.begin(), blocks.end(), [](const Block& x, const Block& y) {
    return x.bound > y.bound || (x.bound == y.bound && x.order < y.order);
  });
  stack.insert(stack.end(), blocks.rbegin(), blocks.rend());
}

}  // namespace bnb

/// The result of exhaustive_search, bit for bit, from blocks of at most 2^top translations
/// per axis: `bound` must hold levels 0..top.
template <typename Bound>
std::optional<GridHit> branch_and_bound(const IndexGrid& g, std::size_t top, const Bound& bound, int to_beat) {
  const auto block = [&](std::size_t level, int a, int i, int j) {
    return bnb::Block{level, a, i, j, bound(level, a, i, j), g.order(a, i, j)};
  };
  std::vector<bnb::Block> stack, children;
  const int side = 1 << top;
  for (int a = -g.na; a <= g.na; ++a) {
    for (int i = -g.n; i <= g.n; i += side) {
      for (int j = -g.n; j <= g.n; j += side) children.push_back(block(top, a, i, j));
    }
  }
  bnb::push_sorted(children, stack);
  std::optional<GridHit> best;
  long best_order = -1;  // below every index: none ties with `to_beat` and wins
  while (!stack.empty()) {
    const bnb::Block b = stack.back();
    stack.pop_back();
    if (b.bound < to_beat || (b.bound == to_beat && b.order > best_order)) continue;
    if (b.level == 0) {
      to_beat = b.bound;
      best = GridHit{b.a, b.i, b.j, b.bound};
      best_order = b.order;
      continue;
    }
    const int half = 1 << (b.level - 1);
    children.clear();
    for (int di : {0, half}) {
      for (int dj : {0, half}) {
        if (b.i + di <= g.n && b.j + dj <= g.n) children.push_back(block(b.level - 1, b.a, b.i + di, b.j + dj));
      }
    }
    bnb::push_sorted(children, stack);
  }
  return best;
}

}  // namespace lookahead::slam::segslam::detail
