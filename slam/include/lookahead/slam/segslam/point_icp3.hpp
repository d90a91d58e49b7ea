// SPDX-License-Identifier: MIT
// ICP for SegSLAM 3D matching (Fairfield et al. 2010, sec. 4.5: "ICP on octree-binned point
// clouds"): the window's end points, one per bin, aligned to a submap's occupied voxel
// centres. The transform is level (x, y, z, yaw): submap frames are gravity-aligned.
//
// Deviation: point-to-plane (normals by PCA of the target's neighbours) instead of point-to-
// point, as in 2D: with one point per 0.2 m bin, point-to-point stalls up to half a bin off
// along walls and floors.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

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

/// A target cloud with its normals and a hash grid for nearest-neighbour queries.
class IcpTarget3 {
 public:
  IcpTarget3(Points3 points, double max_distance);
  [[nodiscard]] std::size_t size() const { return points_.size(); }
  [[nodiscard]] double max_distance() const { return cell_; }
  /// The index of the target point nearest to `q` within max_distance, -1 when none.
  [[nodiscard]] long nearest(const Eigen::Vector3d& q) const;
  [[nodiscard]] const Eigen::Vector3d& point(long i) const { return points_[static_cast<std::size_t>(i)]; }
  /// Unit normal of point i; zero when its neighbourhood is too small to fit a plane.
  [[nodiscard]] const Eigen::Vector3d& normal(long i) const { return normals_[static_cast<std::size_t>(i)]; }

 private:
  [[nodiscard]] std::int64_t cell_key(const Eigen::Vector3d& p, int dx = 0, int dy = 0, int dz = 0) const;
  template <class F>
  void for_each_near(const Eigen::Vector3d& q, F&& f) const;

  Points3 points_;
  Points3 normals_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<long>> cells_;
};

struct Icp3Result {
  Pose4 transform;            ///< source frame -> target frame
  double mean_error = 0.0;    ///< mean point-to-plane distance of the inliers [m]
  double inlier_ratio = 0.0;  ///< share of source points with a correspondence
};

/// Point-to-plane ICP (Gauss-Newton on x, y, z, yaw) of `source` onto `target` from `initial`.
Icp3Result icp_point_to_plane(const Points3& source, const IcpTarget3& target, const Pose4& initial,
                              const Icp3Options& options);

}  // namespace lookahead::slam::segslam
