// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission_options.hpp"

#include <stdexcept>

#include "lookahead/exploration/recovery_behaviour.hpp"
#include "lookahead/exploration/target_strategy.hpp"

namespace lookahead::exploration {
namespace {

// The mission's look-ahead mapping (docs/algorithms/exploration.md has the evidence):
// - surroundings of 14 m first, walls on at most 5 % of the explored free cells, the
//   predictor's 10 m surroundings when they give no hypothesis (a large window alone matches
//   rarely in buildings with few repeats);
// - control points up to 5 m, the radius of S_f (the paper's "preset range" has no value);
// - a frontier is left out when its region within 7 m (half the large surroundings), closed
//   by walls, wall gaps up to 0.5 m and at most the robot's diameter (no way through;
//   Mission::skip_rule) and the world's extent (Fig. 7(d) assumes the boundary known), is
//   predicted or a closed pocket of at most 1 m^2 (a wall sliver);
// - an idle predictor predicts the nearest frontiers not covered yet.
void look_ahead_as_on_the_maze(LookaheadOptions& l) {
  l.predictor.large_surroundings_diameter = 14.0;
  l.predictor.large_max_conflict_share = 0.05;
  l.predictor.control_point_range = 5.0;
  l.skip = SkipVariant::kRegion;
  l.skip_region_radius = 7.0;
  l.skip_region_wall_gap = 0.5;
  l.known_boundary = true;
  l.skip_wall_slivers = true;
  l.predict_while_idle = true;
}

}  // namespace

MissionOptions MissionOptions::defaults() {
  MissionOptions o;
  o.slam.particles = 30;
  // A simulated laser's no-return means "nothing within range": clear free space with it.
  o.slam.insert.clear_no_returns = true;
  o.slam.insert.exact_rays = true;  // long grazing beams would erase corridor walls
  // Planning ends by a sample count, not the clock: fast, and the same on any machine.
  o.planner.time_budget = 10.0;  // used by searches without a sample budget only
  o.planner.max_samples = 3000;
  // Searches bounded by the Dijkstra price sample their ellipse this densely: a short hop
  // takes a few hundred samples, a long detour up to max_samples.
  o.planner.samples_per_m2 = 50.0;
  o.blacklist.lifetime = 120.0;
  o.planner.costmap.unknown_is_free = true;  // frontier goals border unknown space
  // One net hit blocks a cell for the planner (a hit adds 0.85 to the log-odds, 0.65 is
  // log-odds 0.62). With SLAM in the loop the map gets a scan per filter update (every
  // 0.5 m / 0.25 rad), not per laser period, and walls the robot drives along erode under
  // grazing beams to between one and two net hits: at a two-hit bar the planner drew paths
  // through them and the reactive stop caught the robot at the wall (docs/results.md).
  o.planner.costmap.occupied_threshold = 0.65;
  o.follower.lookahead = 0.35;  // short: cut corners less in doorways
  // The 1 deg beams of the 8 m laser end 0.14 m (2.8 cells) apart: at the far end of a
  // corridor longer than the range the frontier is a row of specks 2-3 cells apart, and
  // with a gap of 1 none of them makes a cluster, so the corridor would look explored.
  o.frontiers.cluster_gap = 3;
  // The paper's conservative Psi threshold (sec. III-C): a lower one lets hypotheses with
  // many wrong cells into the look-ahead map.
  o.lookahead.predictor.similarity_threshold = 0.7;
  // Skip a frontier only when its whole unexplored region (closed by explored or predicted
  // walls) is predicted, not when the first unknown cells beyond it are: a hypothesis that
  // covers only the mouth of a wing would have the wing skipped, neither explored nor
  // predicted. The region's radius and the rest of the rule: look_ahead_as_on_the_maze.
  look_ahead_as_on_the_maze(o.lookahead);
  o.harmonize();
  return o;
}

void MissionOptions::harmonize() {
  planner.costmap.robot_radius = robot.radius + safety_margin;
  planner.costmap.safety_margin = safety_margin;
  frontiers.robot_radius = robot.radius + safety_margin;
  frontiers.free_threshold = free_threshold;
  follower.max_linear_speed = robot.max_speed;
  follower.max_turn_rate = robot.max_turn_rate;
  slam.likelihood.max_range = laser.max_range;
  laser.seed = seed;
  odometry.seed = seed + 1;
  slam.seed = seed + 2;
  planner.seed = static_cast<std::uint32_t>(seed + 3);
  // Predictions are made when the strategy needs them or the filter uses them.
  try {
    lookahead.enabled = lookahead.enabled || make_strategy(strategy)->uses_prediction() || slam.prediction.enabled;
  } catch (const std::invalid_argument&) {
    // an unknown strategy name: validate() reports it
  }
}

void MissionOptions::validate() const {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("mission option out of range: ") + what);
  };
  make_strategy(strategy);               // throws on an unknown name
  parse_recovery_order(recovery_order);  // throws on an unknown or repeated name
  require(lookahead.latency >= 0, "lookahead.latency >= 0");
  require(lookahead.targets_per_selection >= 1, "lookahead.targets_per_selection >= 1");
  require(lookahead.skip_region_wall_gap >= 0, "lookahead.skip_region_wall_gap >= 0");
  // known_boundary and skip_wall_slivers (on by default) shape the region variant's
  // regions; the far-side variant has none and ignores them.
  require(lookahead.repredict_after > 0, "lookahead.repredict_after > 0");
  require(lookahead.repredict_growth >= 0, "lookahead.repredict_growth >= 0");
  require(lookahead.skip_confidence >= 0 && lookahead.skip_confidence <= 1, "lookahead.skip_confidence in [0, 1]");
  require(lookahead.skip_region_radius > 0, "lookahead.skip_region_radius > 0");
  require(lookahead.skip_share > 0 && lookahead.skip_share <= 1, "lookahead.skip_share in (0, 1]");
  predictor::validate(lookahead.predictor);
  require(rate_offset > 0, "rate_offset > 0");
  require(time_limit > 0, "time_limit > 0");
  require(coverage_goal > 0 && coverage_goal <= 1, "coverage_goal in (0, 1]");
  require(goal_check_period > 0 && metrics_period > 0, "periods > 0");
  require(stuck_time > 0 && max_goal_attempts >= 1, "stuck_time > 0, max_goal_attempts >= 1");
  require(blacklist.max_strikes >= 1, "blacklist.max_strikes >= 1");
  require(frame_period >= 0, "frame_period >= 0");
  require(free_threshold > 0 && free_threshold < 0.5, "free_threshold in (0, 0.5)");
  require(safety_margin >= 0 && stop_distance >= 0, "safety_margin, stop_distance >= 0");
  robot.validate();
  laser.validate();
  odometry.validate();
  planner::validate(planner);
  planner::validate(follower);
}

}  // namespace lookahead::exploration
