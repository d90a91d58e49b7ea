// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/near_field.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lookahead/slam/grid/grid_tile.hpp"

namespace lookahead::slam::segslam {
namespace {

// row |= row shifted by s bits towards higher cells (bit k -> k + s).
void or_shifted(std::vector<std::uint64_t>& row, std::size_t offset, std::size_t words, int s) {
  const std::size_t q = static_cast<std::size_t>(s) / 64;
  const int r = s % 64;
  for (std::size_t i = words; i-- > q;) {
    std::uint64_t v = row[offset + i - q] << r;
    if (r && i > q) v |= row[offset + i - q - 1] >> (64 - r);
    row[offset + i] |= v;
  }
}

}  // namespace

NearField::NearField(const OccupancyGrid& map, int max_dist2, const std::vector<int>& dilations)
    : resolution_(map.resolution()) {
  Bits base;
  CellIndex lo, hi;
  if (map.known_bounds(lo, hi)) {  // whole tiles: the distance field lives in them too
    base.x0 = lo.x, base.y0 = lo.y, base.width = hi.x - lo.x + 1, base.height = hi.y - lo.y + 1;
    base.row_words = static_cast<std::size_t>(base.width + 63) / 64;
    base.words.assign(base.row_words * static_cast<std::size_t>(base.height), 0);
    for (int ty = lo.y >> GridTile::kBits; ty <= hi.y >> GridTile::kBits; ++ty) {
      for (int tx = lo.x >> GridTile::kBits; tx <= hi.x >> GridTile::kBits; ++tx) {
        const GridTile* t = map.tile(tx, ty);
        if (!t) continue;
        for (int i = 0; i < GridTile::kCells; ++i) {
          if (t->dist2[static_cast<std::size_t>(i)] > max_dist2) continue;
          const int x = GridTile::first_cell(tx) + (i & (GridTile::kSide - 1)) - base.x0;
          const int y = GridTile::first_cell(ty) + (i >> GridTile::kBits) - base.y0;
          base.words[static_cast<std::size_t>(y) * base.row_words + static_cast<std::size_t>(x >> 6)] |=
              std::uint64_t{1} << (x & 63);
        }
      }
    }
  }
  levels_.push_back(std::move(base));
  for (int w : dilations) {
    if (w < 1) throw std::invalid_argument("NearField: dilation width " + std::to_string(w) + " cells, must be >= 1");
    levels_.push_back(dilated(levels_.front(), w));
  }
}

// The box [c, c + w - 1]^2 reaches w - 1 cells below the base, so the dilated copy starts
// there. Widths grow by doubling: rows OR-ed with themselves shifted by the width covered so
// far, O(log w) passes over the bits.
NearField::Bits NearField::dilated(const Bits& base, int w) {
  Bits d;
  if (base.width == 0) return d;
  d.x0 = base.x0 - (w - 1), d.y0 = base.y0 - (w - 1);
  d.width = base.width + w - 1, d.height = base.height + w - 1;
  d.row_words = static_cast<std::size_t>(d.width + 63) / 64;
  d.words.assign(d.row_words * static_cast<std::size_t>(d.height), 0);
  // Dilated cell c (bit c - x0 + w - 1) must see base cells c .. c + w - 1 (bits
  // c - x0 .. c - x0 + w - 1): copy the base's bits to the same positions, then spread each
  // bit k over k .. k + w - 1, in x and then in y.
  for (int y = 0; y < base.height; ++y) {
    const std::size_t from = static_cast<std::size_t>(y) * base.row_words;
    const std::size_t to = static_cast<std::size_t>(y) * d.row_words;
    for (std::size_t i = 0; i < base.row_words; ++i) d.words[to + i] = base.words[from + i];
  }
  for (int y = 0; y < d.height; ++y) {
    const std::size_t at = static_cast<std::size_t>(y) * d.row_words;
    for (int covered = 1; covered < w;) {
      const int s = std::min(covered, w - covered);
      or_shifted(d.words, at, d.row_words, s);
      covered += s;
    }
  }
  for (int covered = 1; covered < w;) {
    const int s = std::min(covered, w - covered);
    for (int y = d.height; y-- > s;) {
      const std::size_t at = static_cast<std::size_t>(y) * d.row_words,
                        below = static_cast<std::size_t>(y - s) * d.row_words;
      for (std::size_t i = 0; i < d.row_words; ++i) d.words[at + i] |= d.words[below + i];
    }
    covered += s;
  }
  return d;
}

}  // namespace lookahead::slam::segslam
