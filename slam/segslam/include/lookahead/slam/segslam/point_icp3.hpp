// SPDX-License-Identifier: MIT
// ICP for SegSLAM 3D matching (Fairfield et al. 2010, SegSLAM sec. 4.5: "ICP on octree-binned point
// clouds"): the window's end points, one per bin, aligned to a submap's occupied voxel
// centres. The transform is level (x, y, z, yaw): submap frames are gravity-aligned.
//
// Deviation: point-to-plane (normals by PCA of the target's neighbours) instead of point-to-
// point, as in 2D: with one point per 0.2 m bin, point-to-point stalls up to half a bin off
// along walls and floors.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"

namespace lookahead::slam::segslam {

using Points3 = std::vector<Eigen::Vector3d>;

/// One point per cubic bin of side `bin` [m] (the mean of the points that fall in it),
/// in bin order (deterministic).
Points3 bin_points3(const Points3& points, double bin);

struct Icp3Options {
  int iterations = 30;
  double max_distance = 0.4;  ///< correspondences farther than this are outliers [m]
};

/// A target cloud with its normals and a grid of cells of max_distance for nearest-neighbour
/// queries: a dense table over the cloud's bounding box (at most kMaxCells cells; sensor
/// clouds here span tens of metres, 1e5-1e6 cells), so a query reads 27 cells without hashing.
class IcpTarget3 {
 public:
  static constexpr long kMaxCells = 1L << 27;
  /// Throws std::invalid_argument when the cloud's box holds more than kMaxCells cells.
  IcpTarget3(Points3 points, double max_distance);
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  [[nodiscard]] double max_distance() const { return cell_; }
  /// The index of the target point nearest to `q` within max_distance, -1 when none (of
  /// equally near ones the last in cell and index order).
  [[nodiscard]] long nearest(const Eigen::Vector3d& q) const;
  [[nodiscard]] const Eigen::Vector3d& point(long i) const { return points_[static_cast<std::size_t>(i)]; }
  /// Unit normal of point i; zero when its neighbourhood is too small to fit a plane.
  [[nodiscard]] const Eigen::Vector3d& normal(long i) const { return normals_[static_cast<std::size_t>(i)]; }

 private:
  // floor(v / cell) by truncation: the same value as lround(floor(...)) without libm calls.
  [[nodiscard]] long cell_of(double v) const {
    const double c = v / cell_;
    const auto i = static_cast<long>(c);
    return i - (c < static_cast<double>(i) ? 1 : 0);
  }
  void index_cells();
  template <class F>
  void for_each_near(const Eigen::Vector3d& q, F&& f) const;

  Points3 points_;
  Points3 normals_;
  double cell_;
  // Cell (x, y, z) of the box from (x0_, y0_, z0_) holds points first_[c] .. first_[c + 1] - 1
  // of by_cell_ (indices, ascending within a cell).
  long x0_ = 0, y0_ = 0, z0_ = 0, nx_ = 0, ny_ = 0, nz_ = 0;
  std::vector<std::uint32_t> first_;
  std::vector<std::uint32_t> by_cell_;
  Points3 by_cell_points_;  ///< points_[by_cell_[k]]: a cell's points side by side for nearest()
};

struct Icp3Result {
  Pose4 transform;            ///< source frame -> target frame
  double mean_error = 0.0;    ///< mean point-to-plane distance of the inliers [m]
  double inlier_ratio = 0.0;  ///< share of source points with a correspondence
};

/// How `source` placed at `pose` fits `target` without moving it: ICP's correspondences
/// (nearest within max_distance, with a normal) and their mean point-to-plane distance.
Icp3Result point_to_plane_fit(const Points3& source, const IcpTarget3& target, const Pose4& pose);

/// Point-to-plane ICP (Gauss-Newton on x, y, z, yaw) of `source` onto `target` from `initial`.
Icp3Result icp_point_to_plane(const Points3& source, const IcpTarget3& target, const Pose4& initial,
                              const Icp3Options& options);

}  // namespace lookahead::slam::segslam
