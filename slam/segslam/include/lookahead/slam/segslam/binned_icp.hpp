// SPDX-License-Identifier: MIT
// Point-to-line ICP on binned 2D point clouds (Fairfield et al. 2010, SegSLAM sec. 4.5: "ICP on the
// octree-binned point clouds ... reduces the influence of point density"; here the bins are
// the cells of a square grid). Nearest neighbours come from a dense grid of the target's bins.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"

namespace lookahead::slam::segslam {

using Points2 = std::vector<Eigen::Vector2d>;

/// One point (the centroid) per occupied bin of side `bin` [m].
Points2 bin_points(const Points2& points, double bin);

struct IcpResult {
  Pose2 transform;            ///< source frame -> target frame
  double mean_error = 0.0;    ///< mean point-to-line distance of the inlier pairs at the end [m]
  double inlier_ratio = 0.0;  ///< share of source points with a target within max_distance
  int iterations = 0;
};

struct IcpOptions {
  int iterations = 30;
  double max_distance = 0.4;  ///< pairs farther apart are outliers [m]
  double bin = 0.1;           ///< the clouds' bin size (the neighbour search cell) [m]
};

/// A target cloud prepared once for many alignments: its points sorted into bins and the wall
/// normal at each (a closed submap never changes, so SegSLAM prepares it once).
class IcpTarget {
 public:
  IcpTarget(Points2 points, const IcpOptions& options);
  ~IcpTarget();
  IcpTarget(IcpTarget&&) noexcept;
  IcpTarget& operator=(IcpTarget&&) noexcept;
  [[nodiscard]] std::size_t size() const;

 private:
  friend IcpResult icp_binned(const Points2&, const IcpTarget&, const Pose2&, const IcpOptions&);
  struct Data;
  std::unique_ptr<Data> data_;
};

/// Aligns `source` onto `target` starting from `guess`.
IcpResult icp_binned(const Points2& source, const IcpTarget& target, const Pose2& guess, const IcpOptions& options);
/// Same, preparing the target on the fly.
IcpResult icp_binned(const Points2& source, const Points2& target, const Pose2& guess, const IcpOptions& options);

}  // namespace lookahead::slam::segslam
