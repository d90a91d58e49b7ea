// SPDX-License-Identifier: MIT
// The cells of a 2D submap that lie within a distance of an obstacle (its distance field at
// or below a squared distance), as rows of bits over the map's tiles, plus dilated copies ("is any cell of this W x W
// box near?") that bound the coarse match score over a block of poses (coarse_search.hpp). A closed submap never
// changes, so SegSLAM builds this once per match candidate.
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::slam::segslam {

class NearField {
 public:
  /// A cell is near when its squared distance to an obstacle is at most `max_dist2`
  /// [cells^2] (GridTile::kFar - 1: anywhere the distance field reaches). Level 0 is the
  /// field itself; level l (l >= 1) holds, at cell c, whether any cell of
  /// [c.x, c.x + w - 1] x [c.y, c.y + w - 1] is near, for w = dilations[l - 1] [cells].
  NearField(const OccupancyGrid& map, int max_dist2, const std::vector<int>& dilations = {});

  /// floor(v) as an int without the libm call (cell indices in the innermost loops of
  /// matching); exact for every value an int holds.
  static int floor_int(double v) {
    const int i = static_cast<int>(v);
    return i - (v < i);
  }

  [[nodiscard]] double resolution() const { return resolution_; }
  [[nodiscard]] std::size_t levels() const { return levels_.size(); }
  /// Cells outside the map read as not near.
  [[nodiscard]] bool near(std::size_t level, int cx, int cy) const {
    const Bits& b = levels_[level];
    const int x = cx - b.x0, y = cy - b.y0;
    if (x < 0 || y < 0 || x >= b.width || y >= b.height) return false;
    return (b.words[static_cast<std::size_t>(y) * b.row_words + static_cast<std::size_t>(x >> 6)] >> (x & 63)) & 1u;
  }

 private:
  struct Bits {
    int x0 = 0, y0 = 0, width = 0, height = 0;  // first cell and extent [cells]
    std::size_t row_words = 0;
    std::vector<std::uint64_t> words;
  };
  static Bits dilated(const Bits& base, int w);

  double resolution_;
  std::vector<Bits> levels_;
};

}  // namespace lookahead::slam::segslam
