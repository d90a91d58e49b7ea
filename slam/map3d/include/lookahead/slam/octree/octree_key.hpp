// SPDX-License-Identifier: MIT
// Voxel index of the evidence octree and its conversion to and from metres.
//
// Keys follow OctoMap's convention (16 bits per axis, key = floor(coordinate / resolution)
// + 2^15), so a key here and an octomap::OcTreeKey name the same voxel and maps can be
// compared cell by cell. Limits: 2^16 voxels per axis, i.e. +-6553 m at 0.2 m and
// +-2621 m at OctoMap's usual 0.08 m.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>

namespace lookahead::slam {

struct OctreeKey {
  std::uint16_t x = 0, y = 0, z = 0;

  friend bool operator==(const OctreeKey& a, const OctreeKey& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  friend bool operator!=(const OctreeKey& a, const OctreeKey& b) { return !(a == b); }
};

/// Metres <-> keys for one resolution.
class OctreeGrid {
 public:
  static constexpr int kKeyBits = 16;
  static constexpr int kCentre = 1 << (kKeyBits - 1);

  explicit OctreeGrid(double resolution) : resolution_(resolution), inverse_(1.0 / resolution) {}

  [[nodiscard]] double resolution() const { return resolution_; }
  /// The voxel containing `p`; nullopt outside the key range.
  [[nodiscard]] std::optional<OctreeKey> key_of(const Eigen::Vector3d& p) const {
    const long kx = axis_key(p.x()), ky = axis_key(p.y()), kz = axis_key(p.z());
    if (!in_range(kx) || !in_range(ky) || !in_range(kz)) return std::nullopt;
    return OctreeKey{static_cast<std::uint16_t>(kx), static_cast<std::uint16_t>(ky), static_cast<std::uint16_t>(kz)};
  }
  /// Centre of a voxel in metres.
  [[nodiscard]] Eigen::Vector3d centre_of(const OctreeKey& k) const {
    return {axis_centre(k.x), axis_centre(k.y), axis_centre(k.z)};
  }
  [[nodiscard]] double axis_centre(int key) const { return (key - kCentre + 0.5) * resolution_; }
  [[nodiscard]] long axis_key(double coordinate) const {
    return static_cast<long>(std::floor(coordinate * inverse_)) + kCentre;
  }
  static bool in_range(long key) { return key >= 0 && key < (1L << kKeyBits); }

 private:
  double resolution_;
  double inverse_;
};

}  // namespace lookahead::slam
