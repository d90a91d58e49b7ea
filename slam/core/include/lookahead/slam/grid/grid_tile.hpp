// SPDX-License-Identifier: MIT
// A square block of cells: the unit of copy-on-write sharing between particle maps.
#pragma once

#include <array>
#include <cstdint>
#include <limits>

namespace lookahead::slam {

struct GridTile {
  static constexpr int kBits = 5;
  static constexpr int kSide = 1 << kBits;  // 32 x 32 cells (1.6 m at 5 cm)
  static constexpr int kCells = kSide * kSide;
  /// Log-odds in fixed point (kLogOddsScale units per nat); kUnknown = never observed.
  static constexpr int kLogOddsScale = 1000;
  static constexpr std::int16_t kUnknown = std::numeric_limits<std::int16_t>::min();
  /// Squared distance (in cells^2) meaning "no obstacle within the field radius".
  static constexpr std::uint8_t kFar = 255;
  static constexpr std::uint8_t kObstacle = 1;     ///< flags bit: counts for the distance field
  static constexpr std::uint8_t kHitThisScan = 2;  ///< flags bit: set while a scan is inserted

  GridTile() {
    log_odds.fill(kUnknown);
    dist2.fill(kFar);
    flags.fill(0);
  }

  static constexpr int index(int local_x, int local_y) { return (local_y << kBits) | local_x; }
  /// The lowest cell coordinate of tile coordinate `tile` (negative tiles too: a multiplication,
  /// as a left shift of a negative value is undefined in C++17).
  static constexpr int first_cell(int tile) { return tile * kSide; }

  std::array<std::int16_t, kCells> log_odds;
  std::array<std::uint8_t, kCells> dist2;
  std::array<std::uint8_t, kCells> flags;
};

}  // namespace lookahead::slam
