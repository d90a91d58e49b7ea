// SPDX-License-Identifier: MIT
// A world named on the command line or in a study: "office", "maze" or "corridor" (generated),
// or a file: map_server .yaml, Stage .world, or an image (.png/.pgm) with its resolution.
#pragma once

#include <optional>
#include <string>

#include "lookahead/exploration/generated_worlds.hpp"

namespace lookahead::exploration {

struct WorldSpec {
  std::string name = "office";    ///< office | maze | corridor | path to a file
  double image_resolution = 0.0;  ///< [m/pixel], for plain images only: must be stated
  /// Pixel rule of a plain image: "stage" (darker than 128 is a wall) or "only_white"
  /// (only 255 is free: P2 Explore's KTH plans, whose outside is grey).
  std::string pixel_rule = "stage";
  std::optional<slam::Pose2> start;  ///< default: the generator's, or a free spot
  std::uint64_t seed = 1;            ///< for generated worlds
};

/// Loads the world and picks the start; errors (ParseError, invalid_argument) name the file.
GeneratedWorld load_world(const WorldSpec& spec, double robot_radius);

/// Throws std::invalid_argument naming the world and the pose when `start` is not finite,
/// outside the map, or in collision (a wall within `robot_radius`): three distinct messages.
void check_start(const World& world, const std::string& name, const slam::Pose2& start, double robot_radius);

/// A start for a file world: the free spot nearest the middle of the world's free space with
/// at least `clearance` [m] to any wall, on a 0.25 m lattice.
slam::Pose2 default_start(const World& world, double clearance);

}  // namespace lookahead::exploration
