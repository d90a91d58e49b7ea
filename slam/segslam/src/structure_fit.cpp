// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/structure_fit.hpp"

#include <cmath>

namespace lookahead::slam::segslam {
namespace {

constexpr double kNormalAgreement = 0.866;  // cos 30 degrees

Eigen::Vector3d rotate(double yaw, const Eigen::Vector3d& v) {
  const double c = std::cos(yaw), s = std::sin(yaw);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()};
}

}  // namespace

OrientedPoints3 structure_points(const IcpTarget3& cloud) {
  OrientedPoints3 out;
  for (long i = 0; i < static_cast<long>(cloud.size()); ++i) {
    const Eigen::Vector3d& n = cloud.normal(i);
    if (n.isZero() || std::abs(n.z()) >= kStructureMaxNormalZ) continue;
    out.points.push_back(cloud.point(i));
    out.normals.push_back(n);
  }
  return out;
}

StructureFit structure_fit(const OrientedPoints3& window, const IcpTarget3& target, const Pose4& pose,
                           const std::function<Seen(const Eigen::Vector3d&)>& seen) {
  StructureFit f;
  const Pose3 placed = pose.level_pose3();
  double error = 0;
  std::size_t inliers = 0, free = 0;
  for (std::size_t i = 0; i < window.points.size(); ++i) {
    const Eigen::Vector3d q = placed * window.points[i];
    const Seen here = seen(q);
    if (here == Seen::kUnknown) continue;
    ++f.points;
    if (here == Seen::kFree) ++free;
    const long j = target.nearest(q);
    if (j < 0 || target.normal(j).isZero()) continue;
    const Eigen::Vector3d& n = target.normal(j);
    // Normals have no sign: a wall seen from either side is the same wall.
    if (std::abs(n.dot(rotate(pose.yaw, window.normals[i]))) < kNormalAgreement) continue;
    error += std::abs(n.dot(q - target.point(j)));
    ++inliers;
  }
  if (f.points > 0) {
    f.inlier_ratio = static_cast<double>(inliers) / static_cast<double>(f.points);
    f.free_ratio = static_cast<double>(free) / static_cast<double>(f.points);
  }
  f.mean_error = inliers > 0 ? error / static_cast<double>(inliers) : target.max_distance();
  return f;
}

}  // namespace lookahead::slam::segslam
