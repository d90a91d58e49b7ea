// SPDX-License-Identifier: MIT
// One hypothesis of the RBPF: a pose, a map (copy-on-write, shared with its relatives), a
// log weight and its trajectory, a chain of nodes shared with its ancestors.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::slam {

struct TrajectoryNode {
  /// The pose estimate of this update: the mean of the proposal the particle's pose was drawn
  /// from (the drawn pose itself went into the map).
  Pose2 pose;
  std::size_t scan_index = 0;  ///< the scan this pose belongs to
  std::shared_ptr<const TrajectoryNode> parent;

  TrajectoryNode(const Pose2& p, std::size_t scan, std::shared_ptr<const TrajectoryNode> up)
      : pose(p), scan_index(scan), parent(std::move(up)) {}
  // Unlinks the chain iteratively: a recursive release of thousands of nodes could overflow
  // the stack of a worker thread.
  ~TrajectoryNode();
  TrajectoryNode(const TrajectoryNode&) = delete;
  TrajectoryNode& operator=(const TrajectoryNode&) = delete;
};

struct Particle {
  Pose2 pose;
  OccupancyGrid map;
  double log_weight = 0.0;
  std::shared_ptr<const TrajectoryNode> trajectory;
  /// P-SLAM: per active hypothesis, the transform from this particle's map frame into the
  /// hypothesis frame (the best particle's when it was added: sec. IV-B).
  std::vector<Pose2> hypothesis_offsets;
};

}  // namespace lookahead::slam
