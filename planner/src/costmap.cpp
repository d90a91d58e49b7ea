// SPDX-License-Identifier: MIT
#include "lookahead/planner/costmap.hpp"

#include <algorithm>
#include <cmath>

#include "distance_transform.hpp"
#include "option_check.hpp"
#include "segment_walk.hpp"

namespace lookahead::planner {

void validate(const CostmapOptions& o) {
  detail::check_range("CostmapOptions.occupied_threshold", o.occupied_threshold, 0.5, 1.0, "", detail::Bound::kOpen);
  detail::check_range("CostmapOptions.robot_radius", o.robot_radius, 0.0, 5.0, "m");
  detail::check_range("CostmapOptions.margin", o.margin, 0.0, 50.0, "m");
  detail::check_range("CostmapOptions.safety_margin", o.safety_margin, 0.0, o.robot_radius, "m");
}

Costmap::Costmap(const slam::OccupancyGrid& map, const CostmapOptions& options)
    : options_((validate(options), options)), resolution_(map.resolution()) {
  if (!map.known_bounds(known_lo_, known_hi_)) return;  // nothing observed: an empty (all-blocked) costmap
  const int margin_cells = static_cast<int>(std::ceil(options.margin / resolution_));
  origin_ = {known_lo_.x - margin_cells, known_lo_.y - margin_cells};
  width_ = known_hi_.x - known_lo_.x + 1 + 2 * margin_cells;
  height_ = known_hi_.y - known_lo_.y + 1 + 2 * margin_cells;
  free_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  inflate(map, 0, 0, width_ - 1, height_ - 1);
}

void Costmap::update(const slam::OccupancyGrid& map, slam::CellIndex lo, slam::CellIndex hi) {
  slam::CellIndex known_lo, known_hi;
  if (empty() || !map.known_bounds(known_lo, known_hi) || known_lo != known_lo_ || known_hi != known_hi_) {
    *this = Costmap(map, options_);  // the raster's extent follows the known bounds
    return;
  }
  // A cell's status depends on the blocked cells within the radius: the changed cells can
  // only free or block cells up to the radius around them.
  const int r = inflation_reach();
  const int x0 = std::max(0, lo.x - origin_.x - r), y0 = std::max(0, lo.y - origin_.y - r);
  const int x1 = std::min(width_ - 1, hi.x - origin_.x + r), y1 = std::min(height_ - 1, hi.y - origin_.y + r);
  if (x0 <= x1 && y0 <= y1) inflate(map, x0, y0, x1, y1);
}

int Costmap::inflation_reach() const { return static_cast<int>(std::ceil(options_.robot_radius / resolution_)) + 1; }

void Costmap::inflate(const slam::OccupancyGrid& map, int x0, int y0, int x1, int y1) {
  // The blocked cells that can reach the rectangle lie within the radius of it.
  const int r = inflation_reach();
  const int bx0 = std::max(0, x0 - r), by0 = std::max(0, y0 - r);
  const int bw = std::min(width_ - 1, x1 + r) - bx0 + 1, bh = std::min(height_ - 1, y1 + r) - by0 + 1;
  std::vector<std::uint8_t> blocked(static_cast<std::size_t>(bw) * static_cast<std::size_t>(bh));
  mark_blocked_cells(map, bx0, by0, bw, bh, blocked);
  // Inflation: free only if no blocked centre lies within the radius (squared, in cells^2).
  const std::vector<double> d2 = detail::squared_distance_transform(blocked, bw, bh);
  // The epsilon keeps a centre at exactly the radius blocked despite rounding of the division.
  const auto limit = [&](double radius) { return (radius / resolution_) * (radius / resolution_) + 1e-9; };
  const double free_limit = limit(options_.robot_radius);
  const double body_limit = limit(options_.robot_radius - options_.safety_margin);
  for (int y = y0; y <= y1; ++y) {
    const double* row = &d2[static_cast<std::size_t>(y - by0) * static_cast<std::size_t>(bw)];
    for (int x = x0; x <= x1; ++x) {
      const double d = row[x - bx0];
      free_[index(x, y)] = d > free_limit ? kFree : d > body_limit ? kBodyFits : kBlocked;
    }
  }
}

void Costmap::mark_blocked_cells(const slam::OccupancyGrid& map, int x0, int y0, int w, int h,
                                 std::vector<std::uint8_t>& blocked) const {
  // p >= threshold  <=>  log-odds >= logit(threshold): comparing fixed-point log-odds saves
  // an exp() per cell and reads the same decision as OccupancyGrid::probability().
  const double logit = std::log(options_.occupied_threshold / (1.0 - options_.occupied_threshold));
  const double occupied_fixed = logit * slam::GridTile::kLogOddsScale;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::int16_t l = map.raw_log_odds({origin_.x + x0 + x, origin_.y + y0 + y});
      const bool unknown = l == slam::GridTile::kUnknown;
      const bool is_blocked = unknown ? !options_.unknown_is_free : l >= occupied_fixed;
      blocked[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)] =
          is_blocked ? 1 : 0;
    }
  }
}

Point2 Costmap::min_corner() const { return {origin_.x * resolution_, origin_.y * resolution_}; }

Point2 Costmap::max_corner() const { return {(origin_.x + width_) * resolution_, (origin_.y + height_) * resolution_}; }

slam::CellIndex Costmap::cell_at(Point2 p) const {
  // Same floor rule as slam::OccupancyGrid::cell_at, so both agree on every position.
  return {static_cast<int>(std::floor(p.x / resolution_)), static_cast<int>(std::floor(p.y / resolution_))};
}

Point2 Costmap::cell_center(slam::CellIndex c) const { return {(c.x + 0.5) * resolution_, (c.y + 0.5) * resolution_}; }

bool Costmap::contains(slam::CellIndex c) const {
  return c.x >= origin_.x && c.y >= origin_.y && c.x < origin_.x + width_ && c.y < origin_.y + height_;
}

bool Costmap::cell_is_free(slam::CellIndex c) const {
  return contains(c) && free_[index(c.x - origin_.x, c.y - origin_.y)] == kFree;
}

bool Costmap::cell_fits_body(slam::CellIndex c) const {
  return contains(c) && free_[index(c.x - origin_.x, c.y - origin_.y)] != kBlocked;
}

template <typename CellOk>
bool Costmap::segment_passes(Point2 a, Point2 b, CellOk ok) const {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) {
    return false;
  }
  return detail::walk_segment(a.x / resolution_, a.y / resolution_, b.x / resolution_, b.y / resolution_,
                              [&](int x, int y, double) {
                                return ok(slam::CellIndex{x, y});
                              });
}

bool Costmap::segment_is_free(Point2 a, Point2 b) const {
  return segment_passes(a, b, [this](slam::CellIndex c) { return cell_is_free(c); });
}

namespace {

template <typename SegmentOk, typename PointOk>
bool every_segment(const Path& path, SegmentOk segment_ok, PointOk point_ok) {
  if (path.empty()) return false;
  if (path.size() == 1) return point_ok(path.front());
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (!segment_ok(path[i - 1], path[i])) return false;
  }
  return true;
}

}  // namespace

bool Costmap::path_is_free(const Path& path) const {
  return every_segment(
      path, [this](Point2 a, Point2 b) { return segment_is_free(a, b); }, [this](Point2 p) { return is_free(p); });
}

bool Costmap::path_fits_body(const Path& path) const {
  const auto fits = [this](slam::CellIndex c) { return cell_fits_body(c); };
  return every_segment(
      path, [&](Point2 a, Point2 b) { return segment_passes(a, b, fits); }, [this](Point2 p) { return fits_body(p); });
}

std::size_t Costmap::free_cell_count() const {
  return static_cast<std::size_t>(std::count(free_.begin(), free_.end(), kFree));
}

}  // namespace lookahead::planner
