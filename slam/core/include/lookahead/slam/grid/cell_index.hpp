// SPDX-License-Identifier: MIT
// Integer cell coordinates of a grid; separate from metric positions on purpose.
#pragma once

namespace lookahead::slam {

struct CellIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(CellIndex a, CellIndex b) { return a.x == b.x && a.y == b.y; }
  friend bool operator!=(CellIndex a, CellIndex b) { return !(a == b); }
};

}  // namespace lookahead::slam
