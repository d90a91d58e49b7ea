// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/scan_inserter.hpp"

#include <cmath>

namespace lookahead::slam {
namespace {

struct BeamEnd {
  CellIndex cell;
  bool hit;
};

// Caches the tile of the last cell written, so a ray pays the copy-on-write check once per
// tile it crosses rather than once per cell.
class TileCursor {
 public:
  explicit TileCursor(OccupancyGrid& grid) : grid_(grid) {}
  GridTile& at(CellIndex c) {
    const int tx = c.x >> GridTile::kBits;
    const int ty = c.y >> GridTile::kBits;
    if (tile_ == nullptr || tx != tx_ || ty != ty_) {
      tile_ = &grid_.mutable_tile(tx, ty);
      tx_ = tx;
      ty_ = ty;
    }
    return *tile_;
  }
  void invalidate() { tile_ = nullptr; }

 private:
  OccupancyGrid& grid_;
  GridTile* tile_ = nullptr;
  int tx_ = 0, ty_ = 0;
};

std::vector<BeamEnd> beam_ends(const OccupancyGrid& grid, const Pose2& laser,
                               const LaserScan& scan, double usable) {
  std::vector<BeamEnd> ends;
  ends.reserve(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    if (!scan.is_return(i)) continue;
    const double r = std::min<double>(scan.ranges[i], usable);
    const double a = laser.theta + scan.bearing(i);
    ends.push_back({grid.cell_at(laser.x + r * std::cos(a), laser.y + r * std::sin(a)),
                    scan.ranges[i] < usable});
  }
  return ends;
}

}  // namespace

void insert_scan(OccupancyGrid& grid, const Pose2& robot, const LaserScan& scan,
                 const InsertOptions& options) {
  const Pose2 laser = robot.compose(scan.laser_offset);
  const CellIndex origin = grid.cell_at(laser.x, laser.y);
  const std::vector<BeamEnd> ends = beam_ends(grid, laser, scan, options.max_usable_range);
  TileCursor cursor(grid);
  for (const BeamEnd& e : ends) {  // phase 1: mark this scan's hits
    if (e.hit) cursor.at(e.cell).flags[OccupancyGrid::local(e.cell)] |= GridTile::kHitThisScan;
  }
  const int miss = grid.fixed_miss();
  for (const BeamEnd& e : ends) {  // phase 2: misses along every beam, sparing the hits
    trace_cells(origin, e.cell, [&](CellIndex c) {
      if (c == e.cell) return false;
      GridTile& t = cursor.at(c);
      if (!(t.flags[OccupancyGrid::local(c)] & GridTile::kHitThisScan)) {
        grid.add_log_odds_in(t, c, miss);
      }
      return true;
    });
  }
  const int hit = grid.fixed_hit();
  for (const BeamEnd& e : ends) {  // phase 3: hits, once per cell
    if (!e.hit) continue;
    GridTile& t = cursor.at(e.cell);
    std::uint8_t& flags = t.flags[OccupancyGrid::local(e.cell)];
    if (!(flags & GridTile::kHitThisScan)) continue;  // two beams ending in one cell
    flags &= static_cast<std::uint8_t>(~GridTile::kHitThisScan);
    grid.add_log_odds_in(t, e.cell, hit);
  }
  // Non-hit beam ends (cropped at the usable range) are free too.
  for (const BeamEnd& e : ends) {
    if (!e.hit) grid.add_log_odds_in(cursor.at(e.cell), e.cell, miss);
  }
}

}  // namespace lookahead::slam
