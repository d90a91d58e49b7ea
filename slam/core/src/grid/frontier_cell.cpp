// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/frontier_cell.hpp"

#include <cmath>
#include <stdexcept>

namespace lookahead::slam {

namespace {
// The first fixed-point log-odds whose probability reaches p. Comparing raw log-odds against
// it reads exactly the decisions of OccupancyGrid::probability() without an exp() per cell.
int first_log_odds_reaching(double p) {
  const auto probability = [](int l) {
    return 1.0 / (1.0 + std::exp(-static_cast<double>(l) / GridTile::kLogOddsScale));
  };
  int l = static_cast<int>(std::lround(std::log(p / (1.0 - p)) * GridTile::kLogOddsScale));
  while (probability(l) >= p) --l;
  while (probability(l) < p) ++l;
  return l;
}
}  // namespace

FrontierCellTest::FrontierCellTest(const FrontierCellRule& rule) : rule_(rule) {
  if (!(rule.free_threshold > 0 && rule.free_threshold < 0.5) ||
      !(rule.occupied_threshold > 0.5 && rule.occupied_threshold < 1)) {
    throw std::invalid_argument("frontier cell thresholds out of range");
  }
  free_from_ = first_log_odds_reaching(rule.free_threshold);
  occupied_from_ = first_log_odds_reaching(rule.occupied_threshold);
}

// Unexplored is neither free nor occupied. With an undecided band, a cell one grazing beam
// crossed (known, undecided, its evidence leaning free) counts when it lies in the band at
// the edge of the seen region, where such cells separate the free from the never-seen cells
// and would otherwise hide a way out; an undecided cell deep in the known map is a blurred
// wall edge (pose noise) and does not count, or frontier specks would line every wall. An
// undecided cell whose evidence leans occupied was hit more than crossed: a wall that
// grazing beams eroded (a heading error of a fraction of a degree carries a beam along a
// wall's row of cells), not a way out.
bool FrontierCellTest::is_unexplored(const OccupancyGrid& grid, CellIndex n) const {
  const int l = grid.raw_log_odds(n);
  if (l == GridTile::kUnknown) return true;
  if (rule_.undecided_band < 0 || l < free_from_ || l > 0) return false;
  const int b = rule_.undecided_band;
  for (int dy = -b; dy <= b; ++dy)
    for (int dx = -b; dx <= b; ++dx)
      if (!grid.is_known({n.x + dx, n.y + dy})) return true;
  return false;
}

bool FrontierCellTest::is_frontier(const OccupancyGrid& grid, CellIndex c) const {
  if (!is_free(grid, c)) return false;
  // 4-neighbourhood: a diagonal unknown cell alone is a gap between beams, not a way out.
  const bool borders_unexplored = is_unexplored(grid, {c.x + 1, c.y}) || is_unexplored(grid, {c.x - 1, c.y}) ||
                                  is_unexplored(grid, {c.x, c.y + 1}) || is_unexplored(grid, {c.x, c.y - 1});
  if (!borders_unexplored || !rule_.skip_wall_cells) return borders_unexplored;
  // A free cell that touches a wall and unknown space is the unseen inside of that wall
  // (beams graze a wall and leave gaps between its hits), not a way into new space: going
  // there can never clear it. Undecided cells that lean occupied count as wall here: an
  // eroded wall seen from a pose with some error is mostly such cells.
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (leans_occupied(grid, {c.x + dx, c.y + dy})) return false;
  return true;
}

}  // namespace lookahead::slam
