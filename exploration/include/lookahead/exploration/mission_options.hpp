// SPDX-License-Identifier: MIT
// Every parameter of an exploration mission, nested by component. Defaults follow the
// P-SLAM paper's Stage setup where it gives one (P3-DX at 0.2 m/s, SICK LMS-200 180 deg).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "lookahead/exploration/frontier_detector.hpp"
#include "lookahead/exploration/goal_blacklist.hpp"
#include "lookahead/exploration/laser_simulator.hpp"
#include "lookahead/exploration/lookahead_mapping.hpp"
#include "lookahead/exploration/odometry_model.hpp"
#include "lookahead/exploration/robot.hpp"
#include "lookahead/planner/path_follower.hpp"
#include "lookahead/planner/planner_options.hpp"
#include "lookahead/slam/rbpf/rbpf_options.hpp"

namespace lookahead::exploration {

enum class PoseSource {
  kSlam,   ///< the robot localises and maps with the RBPF (SLAM in the loop)
  kTruth,  ///< the map is built at the true pose (planner-only studies)
};

/// mission.pose_source in YAML (a named choice, slam/config/named_choice.hpp).
constexpr std::array<std::pair<PoseSource, const char*>, 2> choice_names(PoseSource) {
  return {{{PoseSource::kSlam, "slam"}, {PoseSource::kTruth, "truth"}}};
}

struct MissionOptions {
  std::string strategy = "nearest";  ///< target selection: nearest | utility | advantage | rate |
                                     ///< predictive[-utility|-advantage|-rate]
  double utility_lambda = 1.0;       ///< utility = gain [m^2] - lambda * cost [m]
  double rate_offset = 4.0;          ///< rate = gain [m^2] / (2 cost - nearest cost + offset) [m], > 0
  PoseSource pose_source = PoseSource::kSlam;
  std::uint64_t seed = 1;          ///< seeds the sensor, odometry, SLAM and planner
  double time_limit = 1800.0;      ///< simulated seconds, > 0
  double coverage_goal = 0.95;     ///< stop at this share of the reachable free area, (0, 1]
  double goal_check_period = 1.0;  ///< how often the current goal is re-examined [s]
  double stuck_time = 30.0;        ///< no progress this long: blacklist the goal [s]
  /// Only on a detour (more than 10 m of path left, over twice the straight distance), a
  /// shorter path left counts as progress too: a ring corridor can lead away from its goal
  /// for minutes, while in a door the margin flickers on the replanned paths stay short.
  bool detour_progress = true;
  int max_goal_attempts = 5;                   ///< candidates tried per selection before "trapped"
  double metrics_period = 1.0;                 ///< coverage is sampled this often [s]
  double frame_period = 2.0;                   ///< animation frame every [s]; 0 = no animation
  double initial_turn = 2 * 3.14159265358979;  ///< turn in place at the start [rad]
  /// The robot's map counts a cell as explored (free) below this occupancy.
  double free_threshold = 0.35;
  /// Planning keeps this much more than the robot's radius from walls [m]: pure pursuit
  /// cuts corners and the costmap's inflation is exact only to a cell. A path already
  /// planned is kept while the body alone fits along it (Costmap::path_fits_body).
  double safety_margin = 0.08;
  /// A reactive stop: no forward motion while a laser end point lies in the robot's swept
  /// corridor within this distance ahead of its body [m] (walls the map has not caught up
  /// with yet).
  double stop_distance = 0.15;
  /// The recovery behaviours tried, in this order, when a selection plans no path to any
  /// frontier (recovery_behaviour.hpp): comma-separated names of backtrack | last_resort |
  /// second_chance | look_around, each at most once; empty: trapped at the first such selection.
  std::string recovery_order = "backtrack, last_resort, second_chance, look_around";

  slam::RbpfOptions slam;
  planner::PlannerOptions planner;
  planner::FollowerOptions follower;
  FrontierOptions frontiers;
  BlacklistOptions blacklist;
  LaserOptions laser;
  RobotOptions robot;
  OdometryNoiseOptions odometry;
  LookaheadOptions lookahead;  ///< P-SLAM look-ahead mapping (predictions at each new target)

  /// The defaults above, with the dependent settings made consistent (robot radius and
  /// speed in the planner, follower and frontier options, 10 Hz updates of the RBPF...).
  static MissionOptions defaults();
  /// Re-derives the dependent settings after a change (call after editing robot/laser).
  void harmonize();
  void validate() const;  ///< throws std::invalid_argument naming the field
};

}  // namespace lookahead::exploration
