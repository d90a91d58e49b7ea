// SPDX-License-Identifier: MIT
// What SegSLAM 3D matching asks of a closed submap's voxels, as dense tables over its occupied
// bounding box (Fairfield et al. 2010, SegSLAM sec. 4.5): is a point near an occupied voxel (the
// coarse search's score and the structure test), has the map observed it at all (the
// structure test's free space), and the coarse search's bounds over blocks of poses
// (level_coarse_search.hpp). A closed submap never changes, so matching builds this once per
// candidate (OctreeMatchTarget) and every particle and attempt reads it.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lookahead/slam/octree/evidence_octree.hpp"
#include "lookahead/slam/segslam/structure_fit.hpp"

namespace lookahead::slam::segslam {

class NearOccupiedField {
 public:
  /// The table of `map`; `bound_widths` (at most 5, not decreasing, each >= 1) adds the
  /// coarse search's bound levels 1.. (near_in_plane(level, ...)).
  explicit NearOccupiedField(const EvidenceOctree& map, const std::vector<int>& bound_widths = {});
  [[nodiscard]] bool near(const Eigen::Vector3d& p) const;
  /// Within one voxel of an occupied one in x and y and kLevelReach voxels in z: the coarse
  /// search's test, which leaves z to ICP: the map sample's guess may be a few decimetres off
  /// in height at a loop's closure, and a 27-voxel test then misses the floor and ceiling.
  [[nodiscard]] bool near_in_plane(const Eigen::Vector3d& p) const;
  static constexpr long kLevelReach = 2;
  /// Near an occupied voxel, else known (free), else unknown.
  [[nodiscard]] Seen seen(const Eigen::Vector3d& p) const;

  [[nodiscard]] double resolution() const { return grid_.resolution(); }
  /// The voxel key of a coordinate: OctreeGrid::axis_key's value, with floor done by
  /// truncation (no libm call in the coarse search's innermost loop).
  [[nodiscard]] long axis_key(double coordinate) const {
    const double v = coordinate * inverse_;
    const auto i = static_cast<long>(v);
    return i - (v < static_cast<double>(i) ? 1 : 0) + OctreeGrid::kCentre;
  }
  /// Level 0: near_in_plane of voxel (kx, ky, kz). Level l >= 1: is any voxel of
  /// [kx, kx + w - 1] x [ky, ky + w - 1] at height kz near in the plane, w = bound_widths[l - 1]?
  /// Every level is a bit of one table, so a block's levels share cache lines.
  [[nodiscard]] bool near_in_plane(std::size_t level, long kx, long ky, long kz) const {
    return (bits_at_key(kx, ky, kz) >> (kLevelShift + level)) & 1u;
  }
  /// Bound levels above 0.
  [[nodiscard]] std::size_t bound_levels() const { return bound_widths_.size(); }
  [[nodiscard]] const std::vector<int>& bound_widths() const { return bound_widths_; }

 private:
  [[nodiscard]] std::uint8_t bits_at_key(long kx, long ky, long kz) const {
    const long x = kx - x0_, y = ky - y0_, z = kz - z0_;
    if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return 0;
    return bits_[static_cast<std::size_t>((z * ny_ + y) * nx_ + x)];
  }
  [[nodiscard]] std::uint8_t bits_at(const Eigen::Vector3d& p) const {
    return bits_at_key(axis_key(p.x()), axis_key(p.y()), axis_key(p.z()));
  }
  void build_bounds();

  // A voxel's bits: near an occupied voxel, observed, near in the plane (bound level 0), then
  // bound levels 1.. .
  static constexpr std::uint8_t kNear = 1, kObserved = 2, kNearInPlane = 4;
  static constexpr int kLevelShift = 2;

  OctreeGrid grid_{1.0};
  double inverse_ = 1.0;  // 1 / resolution, as OctreeGrid computes it
  std::vector<int> bound_widths_;
  long x0_ = 0, y0_ = 0, z0_ = 0, nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::uint8_t> bits_;
};

}  // namespace lookahead::slam::segslam
