// SPDX-License-Identifier: MIT
#include "lookahead/predictor/similarity.hpp"

#include <cmath>
#include <stdexcept>

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
  occupied_.assign(n, 0);
  known_.assign(n, 0);
  const std::int16_t on =
      static_cast<std::int16_t>(std::lround(1000.0 * std::log(occupied_threshold / (1.0 - occupied_threshold))));
  for (int cy = lo.y; cy <= hi.y; ++cy) {
    for (int cx = lo.x; cx <= hi.x; ++cx) {
      const std::int16_t l = grid.raw_log_odds({cx, cy});
      if (l == slam::GridTile::kUnknown) continue;
      const int u = static_cast<int>(((cx + 0.5) * fine - x0_) / res_);
      const int v = static_cast<int>(((cy + 0.5) * fine - y0_) / res_);
      const auto k = static_cast<std::size_t>(v * w_ + u);
      known_[k] = 1;
      if (l >= on) occupied_[k] = 1;
    }
  }
  near_ = occupied_;
  if (tolerance_cells == 0) return;
  for (int v = 0; v < h_; ++v) {
    for (int u = 0; u < w_; ++u) {
      if (!occupied_[static_cast<std::size_t>(v * w_ + u)]) continue;
      for (int dv = -tolerance_cells; dv <= tolerance_cells; ++dv) {
        for (int du = -tolerance_cells; du <= tolerance_cells; ++du) {
          const int uu = u + du, vv = v + dv;
          if (uu >= 0 && vv >= 0 && uu < w_ && vv < h_) near_[static_cast<std::size_t>(vv * w_ + uu)] = 1;
        }
      }
    }
  }
}

bool CoarseOccupancy::read(const std::vector<std::uint8_t>& layer, double x, double y) const {
  const int u = static_cast<int>(std::floor((x - x0_) / res_));
  const int v = static_cast<int>(std::floor((y - y0_) / res_));
  if (u < 0 || v < 0 || u >= w_ || v >= h_) return false;
  return layer[static_cast<std::size_t>(v * w_ + u)] != 0;
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

SimilarityScore similarity(const CoarseOccupancy& target_map, const CoarseOccupancy& reference_map,
                           const RegionSamples& region, const slam::Pose2& reference_to_target) {
  // Each target sample p looks up its reference point q = T^-1 (+) p.
  const slam::Pose2 inv = reference_to_target.inverse();
  const double c = std::cos(inv.theta), s = std::sin(inv.theta);
  SimilarityScore score;
  int shared = 0;  // I(i, j), counted from both sides
  for (std::size_t k = 0; k < region.x.size(); ++k) {
    const double px = region.x[k], py = region.y[k];
    const double qx = inv.x + c * px - s * py, qy = inv.y + s * px + c * py;
    const bool t_occ = target_map.occupied(px, py);
    const bool r_occ = reference_map.occupied(qx, qy);
    score.target_occupied += t_occ;
    score.reference_occupied += r_occ;
    const bool t_near = target_map.near_occupied(px, py), r_near = reference_map.near_occupied(qx, qy);
    shared += (t_occ && r_near) + (r_occ && t_near);
    score.conflicts +=
        (t_occ && !r_near && reference_map.known(qx, qy)) + (r_occ && !t_near && target_map.known(px, py));
    if (!target_map.known(px, py) && reference_map.known(qx, qy)) ++score.new_known;
  }
  const int total = score.target_occupied + score.reference_occupied;
  score.psi = total > 0 ? static_cast<double>(shared) / total : 0.0;
  return score;
}

}  // namespace lookahead::predictor
