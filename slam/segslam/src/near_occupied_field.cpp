// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/near_occupied_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lookahead::slam::segslam {
namespace {

// v[i] |= v[i + s] along a row of `count` cells from `first`: each cell holding the OR of
// itself and the covered - 1 cells after it then holds that of the w - 1 after it (the width
// covered at most doubles per pass).
void spread(std::vector<std::uint8_t>& v, std::size_t first, std::size_t count, int covered, int w) {
  while (covered < w) {
    const auto s = static_cast<std::size_t>(std::min(covered, w - covered));
    for (std::size_t i = 0; i + s < count; ++i) v[first + i] |= v[first + i + s];
    covered += static_cast<int>(s);
  }
}

// The same in y over rows of `width` cells, row by row (the cells of a row are contiguous).
void spread_rows(std::vector<std::uint8_t>& v, std::size_t width, std::size_t rows, int covered, int w) {
  while (covered < w) {
    const auto s = static_cast<std::size_t>(std::min(covered, w - covered));
    for (std::size_t y = 0; y + s < rows; ++y) {
      for (std::size_t x = 0; x < width; ++x) v[y * width + x] |= v[(y + s) * width + x];
    }
    covered += static_cast<int>(s);
  }
}

}  // namespace

NearOccupiedField::NearOccupiedField(const EvidenceOctree& map, const std::vector<int>& bound_widths)
    : grid_(map.grid().resolution()), inverse_(1.0 / map.grid().resolution()), bound_widths_(bound_widths) {
  if (bound_widths_.size() > 5) throw std::invalid_argument("NearOccupiedField: at most 5 bound levels");
  for (std::size_t l = 0; l < bound_widths_.size(); ++l) {
    if (bound_widths_[l] < 1 || (l > 0 && bound_widths_[l] < bound_widths_[l - 1])) {
      throw std::invalid_argument("NearOccupiedField: bound width " + std::to_string(bound_widths_[l]) +
                                  " must be >= 1 and not below the one before");
    }
  }
  const auto above = static_cast<float>(map.options().occupied_above);
  std::vector<OctreeKey> occupied;
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    if (l > above) occupied.push_back(k);
  });
  if (occupied.empty()) return;
  long x1 = 0, y1 = 0, z1 = 0;
  x0_ = y0_ = z0_ = std::numeric_limits<long>::max();
  for (const auto& k : occupied) {
    x0_ = std::min<long>(x0_, k.x), y0_ = std::min<long>(y0_, k.y), z0_ = std::min<long>(z0_, k.z);
    x1 = std::max<long>(x1, k.x), y1 = std::max<long>(y1, k.y), z1 = std::max<long>(z1, k.z);
  }
  // The occupied box grown by one voxel (kLevelReach in z), and in x and y by the widest
  // bound's reach below it, where a block's first pose may put a point whose block reaches in.
  const long pad = bound_widths_.empty() ? 0 : bound_widths_.back() - 1;
  x0_ -= 1 + pad, y0_ -= 1 + pad, z0_ -= kLevelReach;
  nx_ = x1 - x0_ + 2, ny_ = y1 - y0_ + 2, nz_ = z1 - z0_ + 1 + kLevelReach;
  bits_.assign(static_cast<std::size_t>(nx_ * ny_ * nz_), 0);
  for (const auto& k : occupied) {
    for (long dz = -kLevelReach; dz <= kLevelReach; ++dz) {
      for (long dy = -1; dy <= 1; ++dy) {
        for (long dx = -1; dx <= 1; ++dx) {
          const long x = k.x - x0_ + dx, y = k.y - y0_ + dy, z = k.z - z0_ + dz;
          bits_[static_cast<std::size_t>((z * ny_ + y) * nx_ + x)] |=
              std::abs(dz) <= 1 ? kNear | kNearInPlane : kNearInPlane;
        }
      }
    }
  }
  map.for_each_voxel([&](const OctreeKey& k, float) {
    const long x = k.x - x0_, y = k.y - y0_, z = k.z - z0_;
    // Observed voxels within one voxel of the occupied box only (the structure test's free
    // space), however far the box is padded for near_in_plane and its bounds.
    if (x < pad || y < pad || z < kLevelReach - 1 || x >= nx_ || y >= ny_ || z >= nz_ - (kLevelReach - 1)) return;
    bits_[static_cast<std::size_t>((z * ny_ + y) * nx_ + x)] |= kObserved;
  });
  build_bounds();
}

// Each bound level's bit: the near-in-plane bits of one height slice spread over the w - 1
// voxels after each in x and then in y.
void NearOccupiedField::build_bounds() {
  const auto plane_size = static_cast<std::size_t>(nx_ * ny_);
  std::vector<std::uint8_t> plane(plane_size);
  for (long z = 0; z < nz_; ++z) {
    const std::size_t slice = static_cast<std::size_t>(z) * plane_size;
    for (std::size_t i = 0; i < plane_size; ++i) plane[i] = (bits_[slice + i] & kNearInPlane) != 0 ? 1 : 0;
    // Widths grow with the level, so each level spreads the one below by what it lacks.
    int covered = 1;
    for (std::size_t l = 0; l < bound_widths_.size(); ++l) {
      const int w = bound_widths_[l];
      for (long y = 0; y < ny_; ++y)
        spread(plane, static_cast<std::size_t>(y * nx_), static_cast<std::size_t>(nx_), covered, w);
      spread_rows(plane, static_cast<std::size_t>(nx_), static_cast<std::size_t>(ny_), covered, w);
      covered = w;
      for (std::size_t i = 0; i < plane_size; ++i)
        bits_[slice + i] |= static_cast<std::uint8_t>(plane[i] << (kLevelShift + l + 1));
    }
  }
}

bool NearOccupiedField::near(const Eigen::Vector3d& p) const { return (bits_at(p) & kNear) != 0; }

bool NearOccupiedField::near_in_plane(const Eigen::Vector3d& p) const { return (bits_at(p) & kNearInPlane) != 0; }

Seen NearOccupiedField::seen(const Eigen::Vector3d& p) const {
  const std::uint8_t b = bits_at(p);
  return (b & kNear) != 0 ? Seen::kNearOccupied : (b & kObserved) != 0 ? Seen::kFree : Seen::kUnknown;
}

}  // namespace lookahead::slam::segslam
