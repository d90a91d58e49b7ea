// SPDX-License-Identifier: MIT
// The picture of a mission a person reads at a glance: the robot's map over the whole world
// (the true walls faint where still unexplored), the true path, the estimated path, the
// frontiers, the current path and goal, and the start.
#pragma once

#include <string>

#include "lookahead/exploration/mission.hpp"
#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::exploration {

/// The robot's map resampled over the world's extent, so every frame has the same size.
slam::ProbabilityMap map_over_world(const slam::OccupancyGrid& map, const World& world);

slam::BgrImage render_mission(const Mission& mission, const std::string& title);

}  // namespace lookahead::exploration
