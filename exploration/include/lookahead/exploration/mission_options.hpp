// SPDX-License-Identifier: MIT
// Every parameter of an exploration mission, nested by component. Defaults follow the
// P-SLAM paper's Stage setup where it gives one (P3-DX at 0.2 m/s, SICK LMS-200 180 deg).
#pragma once

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

struct MissionOptions {
  std::string strategy = "nearest";  ///< target selection: nearest | utility | advantage |
                                     ///< predictive[-utility|-advantage]
  double utility_lambda = 1.0;       ///< utility = gain [m^2] - lambda * cost [m]
  /// The gain counts only unknown area in line of sight of the goal (walls occlude); false:
  /// the whole disc within sensor range, space behind outer walls included.
  bool gain_line_of_sight = true;
  PoseSource pose_source = PoseSource::kSlam;
  std::uint64_t seed = 1;            ///< seeds the sensor, odometry, SLAM and planner
  double time_limit = 1800.0;        ///< simulated seconds, > 0
  double coverage_goal = 0.95;       ///< stop at this share of the reachable free area, (0, 1]
  double goal_check_period = 1.0;    ///< how often the current goal is re-examined [s]
  double stuck_time = 30.0;          ///< no progress this long: blacklist the goal [s]
  /// Progress towards a goal is also a shorter path left to drive, not only a shorter
  /// straight line: a path around a wall can lead away from its goal for longer than
  /// stuck_time.
  bool progress_along_path = false;
  /// Only on a detour (more than 10 m of path left, over twice the straight distance), a
  /// shorter path left counts as progress too: a ring corridor can lead away from its goal
  /// for minutes, while in a door the margin flickers on the replanned paths stay short.
  /// On by default since the costmap's threshold stopped the doors flickering (README,
  /// "Doors that flicker"): with both, all 30 large-plan runs reach 95 % (29 within 4 h).
  bool detour_progress = true;
  int max_goal_attempts = 5;         ///< candidates tried per selection before "trapped"
  double metrics_period = 1.0;       ///< coverage is sampled this often [s]
  double frame_period = 2.0;         ///< animation frame every [s]; 0 = no animation
  double initial_turn = 2 * 3.14159265358979;  ///< turn in place at the start [rad]
  /// The robot's map counts a cell as explored (free) below this occupancy.
  double free_threshold = 0.35;
  /// Planning keeps this much more than the robot's radius from walls [m]: pure pursuit
  /// cuts corners and the costmap's inflation is exact only to a cell.
  double safety_margin = 0.08;
  /// A reactive stop: no forward motion while a laser end point lies in the robot's swept
  /// corridor within this distance ahead of its body [m] (walls the map has not caught up
  /// with yet).
  double stop_distance = 0.15;
  /// When no frontier is reachable, retrace the robot's own trail to the last spot outside
  /// its place on the costmap before calling the robot trapped (breadcrumbs.hpp).
  bool backtrack = true;
  /// The last resort before "trapped": when the ordinary tries (backtracks, looking around)
  /// found no reachable frontier, plan on the map inflated by the robot's body alone (no
  /// safety_margin) and follow that path closely, alternating with backtracks: a door wider
  /// than the robot but narrower than robot + margin is no wall (the KTH plans have
  /// 0.3-0.4 m doors). A mission that never runs out of tries is unchanged by it.
  bool squeeze = true;
  /// Squeeze before the last resort too: when the margin closes the way to a goal still
  /// worth it (a door whose jambs get mapped on the way), and when every frontier the margin
  /// leaves reachable is blacklisted for a while. Needs `squeeze`.
  bool squeeze_when_blocked = false;

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
