// SPDX-License-Identifier: MIT
// The free area a disc robot can reach from a start position: the denominator of every
// coverage figure (DESIGN.md, "Evaluation").
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "lookahead/exploration/world.hpp"

namespace lookahead::exploration {

struct ReachableArea {
  /// Cells holding a place the robot's centre can go: at least the radius from every wall
  /// square, 4-connected to the start (4 so no diagonal squeezes between two corners).
  std::vector<std::uint8_t> centres;
  /// Free cells the robot's body can cover from those centres (centres grown by the radius):
  /// what a coverage metric should count. Row-major like World::cells(); 1 = reachable.
  std::vector<std::uint8_t> reachable;
  std::size_t reachable_cells = 0;
  double area_m2 = 0.0;
  /// False when the start itself is in collision; the masks are then empty (all zero).
  bool start_valid = false;
};

/// Flood fill from `start` [m] for a robot of `robot_radius` [m] (>= 0; 0 = a point robot),
/// with the robot's own collision geometry (a disc against wall squares, as `Robot::step`).
/// The flood runs on samples at most 5 cm apart, so a door a few pixels wide on a coarse plan
/// is open to the count exactly when the robot fits through it (to within a centimetre).
ReachableArea reachable_free_area(const World& world, const Eigen::Vector2d& start, double robot_radius);

/// [m]: how far beyond the reachable free space a wall is still seen (its surface layer).
constexpr double kObservableMargin = 0.15;

/// Cells of the world within `margin` [m] of its reachable area: what a robot can observe, the
/// map a complete exploration builds. Row-major like World::cells(); 1 = observable. Outside
/// it lie the insides of thick walls and pillars and the solid space beyond the outer walls.
std::vector<std::uint8_t> observable_cells(const World& world, const ReachableArea& area,
                                           double margin = kObservableMargin);

}  // namespace lookahead::exploration
