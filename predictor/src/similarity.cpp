// SPDX-License-Identifier: MIT
#include "lookahead/predictor/similarity.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace lookahead::predictor {

CoarseOccupancy::CoarseOccupancy(const slam::OccupancyGrid& grid, double resolution, double occupied_threshold,
                                 int tolerance_cells)
    : res_(resolution) {
  if (!(resolution >= grid.resolution()) || tolerance_cells < 0) {
    throw std::invalid_argument("similarity resolution must be >= the map's; tolerance >= 0");
  }
  slam::CellIndex lo, hi;
  if (!grid.known_bounds(lo, hi)) return;
  const double fine = grid.resolution();
  x0_ = std::floor(lo.x * fine / res_) * res_;
  y0_ = std::floor(lo.y * fine / res_) * res_;
  w_ = static_cast<int>(std::ceil(((hi.x + 1) * fine - x0_) / res_)) + 1;
  h_ = static_cast<int>(std::ceil(((hi.y + 1) * fine - y0_) / res_)) + 1;
  const auto n = static_cast<std::size_t>(w_) * static_cast<std::size_t>(h_);
  cells_.assign(n, 0);
  const std::int16_t on =
      static_cast<std::int16_t>(std::lround(1000.0 * std::log(occupied_threshold / (1.0 - occupied_threshold))));
  for (int cy = lo.y; cy <= hi.y; ++cy) {
    for (int cx = lo.x; cx <= hi.x; ++cx) {
      const std::int16_t l = grid.raw_log_odds({cx, cy});
      if (l == slam::GridTile::kUnknown) continue;
      const int u = static_cast<int>(((cx + 0.5) * fine - x0_) / res_);
      const int v = static_cast<int>(((cy + 0.5) * fine - y0_) / res_);
      std::uint8_t& cell = cells_[static_cast<std::size_t>(v * w_ + u)];
      cell |= kKnown;
      if (l >= on) cell |= kOccupied;
    }
  }
  for (int v = 0; v < h_; ++v) {
    for (int u = 0; u < w_; ++u) {
      if (!(cells_[static_cast<std::size_t>(v * w_ + u)] & kOccupied)) continue;
      for (int dv = -tolerance_cells; dv <= tolerance_cells; ++dv) {
        for (int du = -tolerance_cells; du <= tolerance_cells; ++du) {
          const int uu = u + du, vv = v + dv;
          if (uu >= 0 && vv >= 0 && uu < w_ && vv < h_) cells_[static_cast<std::size_t>(vv * w_ + uu)] |= kNearOccupied;
        }
      }
    }
  }
}

std::uint8_t CoarseOccupancy::flags(double x, double y) const {
  const int u = static_cast<int>(std::floor((x - x0_) / res_));
  const int v = static_cast<int>(std::floor((y - y0_) / res_));
  if (u < 0 || v < 0 || u >= w_ || v >= h_) return 0;
  return cells_[static_cast<std::size_t>(v * w_ + u)];
}

RegionSamples disc_samples(double cx, double cy, double diameter, double resolution) {
  RegionSamples s;
  const double r = diameter / 2;
  const int n = static_cast<int>(std::ceil(r / resolution));
  for (int j = -n; j <= n; ++j) {
    for (int i = -n; i <= n; ++i) {
      const double dx = i * resolution, dy = j * resolution;
      if (dx * dx + dy * dy > r * r) continue;
      s.x.push_back(cx + dx);
      s.y.push_back(cy + dy);
    }
  }
  return s;
}

TargetRegion::TargetRegion(const CoarseOccupancy& target_map, RegionSamples region) : samples(std::move(region)) {
  flags.reserve(samples.x.size());
  for (std::size_t k = 0; k < samples.x.size(); ++k) flags.push_back(target_map.flags(samples.x[k], samples.y[k]));
}

SimilarityScore similarity(const CoarseOccupancy& target_map, const CoarseOccupancy& reference_map,
                           const RegionSamples& region, const slam::Pose2& reference_to_target) {
  return similarity(TargetRegion(target_map, region), reference_map, reference_to_target);
}

SimilarityScore similarity(const TargetRegion& target, const CoarseOccupancy& reference_map,
                           const slam::Pose2& reference_to_target) {
  using C = CoarseOccupancy;
  // Each target sample p looks up its reference point q = T^-1 (+) p.
  const slam::Pose2 inv = reference_to_target.inverse();
  const double c = std::cos(inv.theta), s = std::sin(inv.theta);
  const RegionSamples& region = target.samples;
  SimilarityScore score;
  int shared = 0;  // I(i, j), counted from both sides
  for (std::size_t k = 0; k < region.x.size(); ++k) {
    const double px = region.x[k], py = region.y[k];
    const std::uint8_t t = target.flags[k];
    const std::uint8_t r = reference_map.flags(inv.x + c * px - s * py, inv.y + s * px + c * py);
    const bool t_occ = t & C::kOccupied, r_occ = r & C::kOccupied;
    const bool t_near = t & C::kNearOccupied, r_near = r & C::kNearOccupied;
    const bool t_known = t & C::kKnown, r_known = r & C::kKnown;
    score.target_occupied += t_occ;
    score.reference_occupied += r_occ;
    shared += (t_occ && r_near) + (r_occ && t_near);
    score.conflicts += (t_occ && !r_near && r_known) + (r_occ && !t_near && t_known);
    if (!t_known && r_known) ++score.new_known;
  }
  const int total = score.target_occupied + score.reference_occupied;
  score.psi = total > 0 ? static_cast<double>(shared) / total : 0.0;
  return score;
}

}  // namespace lookahead::predictor
