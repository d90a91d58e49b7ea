// SPDX-License-Identifier: MIT
#include "lookahead/slam/sensor/scan_inserter.hpp"

#include <cmath>

namespace lookahead::slam {
namespace {

struct BeamEnd {
  CellIndex cell;
  bool hit;
  double x, y;  ///< the true end point, in cell units (exact rays)
};

// Caches the tile of the last cell visited, so a ray pays the tile lookup (and the
// copy-on-write check) once per tile it crosses rather than once per cell. Reads do not
// copy: a shared tile is duplicated only when a cell in it really changes.
class TileCursor {
 public:
  explicit TileCursor(OccupancyGrid& grid) : grid_(grid) {}
  const GridTile* peek(CellIndex c) {
    const int tx = c.x >> GridTile::kBits;
    const int ty = c.y >> GridTile::kBits;
    if (tx != tx_ || ty != ty_ || !valid_) {
      tx_ = tx;
      ty_ = ty;
      valid_ = true;
      writable_ = nullptr;
      read_ = grid_.tile(tx, ty);
    }
    return read_;
  }
  GridTile& at(CellIndex c) {
    peek(c);
    if (writable_ == nullptr) read_ = writable_ = &grid_.mutable_tile(tx_, ty_);
    return *writable_;
  }

 private:
  OccupancyGrid& grid_;
  const GridTile* read_ = nullptr;
  GridTile* writable_ = nullptr;
  int tx_ = 0, ty_ = 0;
  bool valid_ = false;
};

// A miss changes nothing on a cell already at the lower clamp that is not an obstacle:
// skipping it keeps the long-known free space of a map shared between particles.
bool miss_changes(const GridTile* t, int i, int floor) {
  return t == nullptr || t->log_odds[i] == GridTile::kUnknown || t->log_odds[i] > floor ||
         (t->flags[i] & (GridTile::kObstacle | GridTile::kHitThisScan)) != 0;
}

std::vector<BeamEnd> beam_ends(const OccupancyGrid& grid, const Pose2& laser, const LaserScan& scan,
                               const InsertOptions& options) {
  const double usable = options.max_usable_range;
  std::vector<BeamEnd> ends;
  ends.reserve(scan.ranges.size());
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const bool clear = !scan.is_return(i) && options.clear_no_returns;
    if (!scan.is_return(i) && !clear) continue;
    const double r = clear ? std::min(scan.max_range, usable) : std::min<double>(scan.ranges[i], usable);
    const double a = laser.theta + scan.bearing(i);
    const double x = laser.x + r * std::cos(a), y = laser.y + r * std::sin(a);
    ends.push_back(
        {grid.cell_at(x, y), !clear && scan.ranges[i] < usable, x / grid.resolution(), y / grid.resolution()});
  }
  return ends;
}

}  // namespace

void insert_scan(OccupancyGrid& grid, const Pose2& robot, const LaserScan& scan, const InsertOptions& options) {
  const Pose2 laser = robot.compose(scan.laser_offset);
  const CellIndex origin = grid.cell_at(laser.x, laser.y);
  const std::vector<BeamEnd> ends = beam_ends(grid, laser, scan, options);
  TileCursor cursor(grid);
  for (const BeamEnd& e : ends) {  // phase 1: mark this scan's hits
    if (e.hit) cursor.at(e.cell).flags[OccupancyGrid::local(e.cell)] |= GridTile::kHitThisScan;
  }
  const int miss = grid.fixed_miss();
  const int floor = grid.fixed_min();
  for (const BeamEnd& e : ends) {  // phase 2: misses along every beam, sparing the hits
    const auto pass = [&](CellIndex c) {
      if (c == e.cell) return false;  // the end cell is phase 3's (or the last loop's)
      const int i = OccupancyGrid::local(c);
      if (!miss_changes(cursor.peek(c), i, floor)) return true;
      GridTile& t = cursor.at(c);
      if (!(t.flags[i] & GridTile::kHitThisScan)) grid.add_log_odds_in(t, c, miss);
      return true;
    };
    if (options.exact_rays) {
      trace_segment(laser.x / grid.resolution(), laser.y / grid.resolution(), e.x, e.y, pass);
    } else {
      trace_cells(origin, e.cell, pass);
    }
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
    if (!e.hit && miss_changes(cursor.peek(e.cell), OccupancyGrid::local(e.cell), floor)) {
      grid.add_log_odds_in(cursor.at(e.cell), e.cell, miss);
    }
  }
}

}  // namespace lookahead::slam
