// SPDX-License-Identifier: MIT
#include "lookahead/slam/grid/occupancy_grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <unordered_set>

#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {
namespace {

int to_fixed(double log_odds) { return static_cast<int>(std::lround(log_odds * GridTile::kLogOddsScale)); }

/// A cell coordinate, clamped to +-2^30 so that a point far off any map (or not finite)
/// becomes a cell the extent check refuses instead of an integer overflow.
int to_cell(double cells) {
  constexpr double kFar = 1 << 30;
  if (!(cells > -kFar)) return -(1 << 30);
  if (!(cells < kFar)) return 1 << 30;
  return static_cast<int>(std::floor(cells));
}

}  // namespace

OccupancyGrid::OccupancyGrid(const GridOptions& options)
    : options_(options),
      hit_(to_fixed(options.log_odds_hit)),
      miss_(to_fixed(options.log_odds_miss)),
      min_(to_fixed(options.log_odds_min)),
      max_(to_fixed(options.log_odds_max)),
      on_(to_fixed(options.obstacle_on)),
      off_(to_fixed(options.obstacle_off)) {
  if (!(options.resolution >= 0.005 && options.resolution <= 1.0)) {
    throw std::invalid_argument("grid resolution must be in [0.005, 1] m");
  }
  if (!(options.log_odds_min < options.obstacle_off && options.obstacle_off < options.obstacle_on &&
        options.obstacle_on < options.log_odds_max)) {
    throw std::invalid_argument("need log_odds_min < obstacle_off < obstacle_on < log_odds_max");
  }
  radius_cells_ = std::max(1, static_cast<int>(std::ceil(options.distance_field_radius / options.resolution)));
  if (radius_cells_ > 15) throw std::invalid_argument("distance_field_radius over 15 cells");
  auto disk = std::make_shared<std::vector<Offset>>();
  for (int dy = -radius_cells_; dy <= radius_cells_; ++dy) {
    for (int dx = -radius_cells_; dx <= radius_cells_; ++dx) {
      const int d2 = dx * dx + dy * dy;
      if (d2 < radius_cells_ * radius_cells_) disk->push_back({dx, dy, d2});
    }
  }
  std::stable_sort(disk->begin(), disk->end(), [](const Offset& a, const Offset& b) { return a.d2 < b.d2; });
  disk_ = std::move(disk);
}

double OccupancyGrid::probability(CellIndex c) const {
  const int l = raw_log_odds(c);
  if (l == GridTile::kUnknown) return 0.5;
  return 1.0 / (1.0 + std::exp(-static_cast<double>(l) / GridTile::kLogOddsScale));
}

CellIndex OccupancyGrid::cell_at(double x, double y) const {
  return {to_cell(x / options_.resolution), to_cell(y / options_.resolution)};
}

void OccupancyGrid::cell_center(CellIndex c, double& x, double& y) const {
  x = (c.x + 0.5) * options_.resolution;
  y = (c.y + 0.5) * options_.resolution;
}

bool OccupancyGrid::known_bounds(CellIndex& min, CellIndex& max) const {
  bool any = false;
  for (int iy = 0; iy < tiles_h_; ++iy) {
    for (int ix = 0; ix < tiles_w_; ++ix) {
      if (!tiles_[static_cast<std::size_t>(iy * tiles_w_ + ix)]) continue;
      const CellIndex lo{GridTile::first_cell(ix + tile_x0_), GridTile::first_cell(iy + tile_y0_)};
      const CellIndex hi{lo.x + GridTile::kSide - 1, lo.y + GridTile::kSide - 1};
      if (!any) {
        min = lo;
        max = hi;
        any = true;
      }
      min = {std::min(min.x, lo.x), std::min(min.y, lo.y)};
      max = {std::max(max.x, hi.x), std::max(max.y, hi.y)};
    }
  }
  return any;
}

void OccupancyGrid::check_extent(std::int64_t tiles_w, std::int64_t tiles_h) const {
  if (tiles_w * tiles_h <= limits::kMaxGridTiles) return;
  const double tile_m = GridTile::kSide * options_.resolution;
  throw limits::ResourceLimitError(
      fmt::format("the map would span {:.0f} m x {:.0f} m ({} x {} tiles of {} m), over the limit of {} tiles "
                  "per grid (limits::kMaxGridTiles); a pose far off the map (odometry jump, huge motion noise?)",
                  static_cast<double>(tiles_w) * tile_m, static_cast<double>(tiles_h) * tile_m, tiles_w, tiles_h,
                  tile_m, limits::kMaxGridTiles));
}

void OccupancyGrid::grow_to_include(int tx, int ty) {
  if (tiles_w_ > 0 && tx >= tile_x0_ && ty >= tile_y0_ && tx < tile_x0_ + tiles_w_ && ty < tile_y0_ + tiles_h_) {
    return;
  }
  // Grow with a margin so a robot driving along an edge does not reallocate every scan.
  constexpr int kMargin = 8;
  const int x0 = tiles_w_ ? std::min(tile_x0_, tx - (tx < tile_x0_ ? kMargin : 0)) : tx - kMargin;
  const int y0 = tiles_h_ ? std::min(tile_y0_, ty - (ty < tile_y0_ ? kMargin : 0)) : ty - kMargin;
  const int x1 =
      tiles_w_ ? std::max(tile_x0_ + tiles_w_, tx + 1 + (tx >= tile_x0_ + tiles_w_ ? kMargin : 0)) : tx + 1 + kMargin;
  const int y1 =
      tiles_h_ ? std::max(tile_y0_ + tiles_h_, ty + 1 + (ty >= tile_y0_ + tiles_h_ ? kMargin : 0)) : ty + 1 + kMargin;
  check_extent(std::int64_t{x1} - x0, std::int64_t{y1} - y0);
  std::vector<std::shared_ptr<GridTile>> grown(static_cast<std::size_t>((x1 - x0) * (y1 - y0)));
  for (int iy = 0; iy < tiles_h_; ++iy) {
    for (int ix = 0; ix < tiles_w_; ++ix) {
      const int nx = ix + tile_x0_ - x0;
      const int ny = iy + tile_y0_ - y0;
      grown[static_cast<std::size_t>(ny * (x1 - x0) + nx)] =
          std::move(tiles_[static_cast<std::size_t>(iy * tiles_w_ + ix)]);
    }
  }
  tiles_ = std::move(grown);
  tile_x0_ = x0;
  tile_y0_ = y0;
  tiles_w_ = x1 - x0;
  tiles_h_ = y1 - y0;
}

GridTile& OccupancyGrid::mutable_tile(int tx, int ty) {
  grow_to_include(tx, ty);
  auto& handle = tiles_[static_cast<std::size_t>((ty - tile_y0_) * tiles_w_ + (tx - tile_x0_))];
  if (!handle) {
    handle = std::make_shared<GridTile>();
  } else if (handle.use_count() > 1) {
    handle = std::make_shared<GridTile>(*handle);  // the copy-on-write step
  } else {
    // Sole owner: another grid may have released its handle from another thread just now.
    // This fence pairs with the release in that handle's decrement, so its reads of the tile
    // happen before our writes.
    std::atomic_thread_fence(std::memory_order_acquire);
  }
  return *handle;
}

void OccupancyGrid::add_log_odds_in(GridTile& t, CellIndex c, int delta) {
  const int i = local(c);
  const int old = t.log_odds[i] == GridTile::kUnknown ? 0 : t.log_odds[i];
  const int now = std::clamp(old + delta, min_, max_);
  t.log_odds[i] = static_cast<std::int16_t>(now);
  const bool was = (t.flags[i] & GridTile::kObstacle) != 0;
  if (!was && now >= on_) {
    t.flags[i] |= GridTile::kObstacle;
    on_became_obstacle(c);
  } else if (was && now <= off_) {
    t.flags[i] &= static_cast<std::uint8_t>(~GridTile::kObstacle);
    on_stopped_being_obstacle(c);
  }
}

void OccupancyGrid::on_became_obstacle(CellIndex c) {
  // A new obstacle can only shorten distances, and only within the field radius.
  for (const Offset& o : *disk_) {
    const CellIndex q{c.x + o.dx, c.y + o.dy};
    const GridTile* ro = tile(q.x >> GridTile::kBits, q.y >> GridTile::kBits);
    if (ro && ro->dist2[local(q)] <= o.d2) continue;  // already as close: no write, no copy
    mutable_tile_of(q).dist2[local(q)] = static_cast<std::uint8_t>(o.d2);
  }
}

int OccupancyGrid::nearest_obstacle_dist2(CellIndex c) const {
  for (const Offset& o : *disk_) {  // sorted by distance: the first obstacle is the nearest
    if (is_obstacle({c.x + o.dx, c.y + o.dy})) return o.d2;
  }
  return GridTile::kFar;
}

void OccupancyGrid::on_stopped_being_obstacle(CellIndex c) {
  // Only cells whose nearest obstacle was c can get farther; recompute just those.
  for (const Offset& o : *disk_) {
    const CellIndex q{c.x + o.dx, c.y + o.dy};
    if (dist2(q) != o.d2) continue;
    const int d2 = nearest_obstacle_dist2(q);
    if (d2 != o.d2) mutable_tile_of(q).dist2[local(q)] = static_cast<std::uint8_t>(d2);
  }
}

std::size_t OccupancyGrid::tile_count() const {
  return static_cast<std::size_t>(
      std::count_if(tiles_.begin(), tiles_.end(), [](const auto& t) { return t != nullptr; }));
}

std::size_t OccupancyGrid::tiles_shared_with(const OccupancyGrid& other) const {
  std::unordered_set<const GridTile*> mine;
  for (const auto& t : tiles_) {
    if (t) mine.insert(t.get());
  }
  return static_cast<std::size_t>(
      std::count_if(other.tiles_.begin(), other.tiles_.end(), [&](const auto& u) { return mine.count(u.get()); }));
}

}  // namespace lookahead::slam
