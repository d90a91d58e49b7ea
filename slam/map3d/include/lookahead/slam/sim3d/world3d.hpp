// SPDX-License-Identifier: MIT
// 3D worlds for the Cave Crawler simulator: an occupancy octree the laser is cast against,
// and the route the robot drives through it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lookahead/slam/octree/evidence_octree.hpp"

namespace lookahead::slam {

struct World3 {
  std::string name;
  EvidenceOctree map;                  ///< occupied voxels are solid; all else is air
  std::vector<Eigen::Vector3d> route;  ///< waypoints of the robot's base on the floor [m]
};

/// A two-level parking garage (84 x 36 m, decks at 0 and 3.3 m, a roof) with an up ramp
/// and a down ramp, columns and seeded parked cars; the route climbs one ramp, drives
/// round the upper deck, comes down the other and returns to its start: a 290 m loop
/// like the CMU garage of SegSLAM Fig. 11.
World3 make_garage_world(std::uint64_t seed, double resolution = 0.1);

/// The real OctoMap of Freiburg building 079 (shared/data/3d/octomap_share_data/geb079.bt)
/// with an out-and-back route along its corridor (about 64 m).
World3 load_geb079_world(const std::string& bt_path);

}  // namespace lookahead::slam
