// SPDX-License-Identifier: MIT
// The structure test of a SegSLAM 3D match: how well the walls, columns and cars of the
// look-ahead window fit those of the candidate submap at the matched pose.
//
// Why: most of a sweep's points are floor and ceiling, which a level transform fits equally
// well at any x, y and yaw. Scored over all points, the mean ICP error of SegSLAM eq. (18)
// (SegSLAM sec. 4.5) is the same for a right and a wrong re-entry metres and tenths of a
// radian off. Only points whose surface is not
// horizontal say where along an aisle and at which yaw the window sits.
#pragma once

#include <cstddef>
#include <functional>

#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/segslam/point_icp3.hpp"

namespace lookahead::slam::segslam {

/// A point's surface counts as structure when its unit normal's vertical component is
/// below this (the surface is steeper than about 45 degrees).
inline constexpr double kStructureMaxNormalZ = 0.7;

/// Points of a cloud with their unit normals.
struct OrientedPoints3 {
  Points3 points;
  Points3 normals;
};

/// The structure points of `cloud` (normals by PCA of its neighbours, as IcpTarget3 fits
/// them): those with a normal whose |z| is below kStructureMaxNormalZ.
OrientedPoints3 structure_points(const IcpTarget3& cloud);

/// What the candidate's map says of a place.
enum class Seen { kUnknown, kFree, kNearOccupied };

struct StructureFit {
  std::size_t points = 0;     ///< structure points tested: those landing where the target has observed
  double inlier_ratio = 0.0;  ///< share with a structure correspondence of the same orientation
  double mean_error = 0.0;    ///< their mean point-to-plane distance [m]
  double free_ratio = 0.0;    ///< share landing in space the candidate saw free: contradictions
};

/// When a match's structure counts as fitted.
struct StructureTestOptions {
  std::size_t min_points = 50;     ///< structure points landing where the candidate observed
  double min_inlier_ratio = 0.15;  ///< share of them with a corresponding surface. 0..1
  /// Share of them that may land where the candidate saw free space: a right re-entry puts
  /// surfaces where the candidate saw surfaces or nothing, not where its beams passed
  /// (right re-entries show 0-0.02 on the garage, wrong ones mostly above 0.07). 0..1
  double max_free_ratio = 0.05;
};

/// `window` placed by `pose` against a target built from structure points only. Only points
/// landing where the target's map has observed are tested (what the candidate never saw
/// neither confirms nor contradicts the match). A point corresponds to its nearest target
/// point within the target's max distance when their normals agree within 30 degrees (a
/// column point next to a floor voxel, or a car's end against a car's side, is not fitted);
/// with no correspondence at all, mean_error is that max distance.
StructureFit structure_fit(const OrientedPoints3& window, const IcpTarget3& target, const Pose4& pose,
                           const std::function<Seen(const Eigen::Vector3d&)>& seen);

}  // namespace lookahead::slam::segslam
