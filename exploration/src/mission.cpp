// SPDX-License-Identifier: MIT
#include "lookahead/exploration/mission.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "lookahead/exploration/prediction_targets.hpp"
#include "lookahead/exploration/run_log.hpp"
#include "lookahead/exploration/target_selection.hpp"
#include "lookahead/exploration/world_source.hpp"
#include "lookahead/slam/sensor/scan_inserter.hpp"

namespace lookahead::exploration {

const char* to_string(MissionStatus s) {
  switch (s) {
    case MissionStatus::kRunning:
      return "running";
    case MissionStatus::kCoverageReached:
      return "coverage_reached";
    case MissionStatus::kDone:
      return "done";
    case MissionStatus::kTrapped:
      return "trapped";
    case MissionStatus::kTimeLimit:
      return "time_limit";
    case MissionStatus::kCollision:
      return "collision";
  }
  return "unknown";
}

namespace {

// Frontier cells this close to a reached goal [m] were in plain view of the robot there;
// the goal lies at most goal_search_radius (1 m) from its cluster.
constexpr double kRetireRadius = 1.0;

// A frontier cluster whose goal lies this close to the current goal [m] is the one the
// robot is driving to (the map grows on the way, so the goal shifts a little).
constexpr double kSameGoalRadius = 1.0;

MissionOptions checked(MissionOptions o) {
  o.validate();
  // The predictive strategy and a filter that uses hypotheses both need predictions made.
  o.lookahead.enabled =
      o.lookahead.enabled || make_strategy(o.strategy)->uses_prediction() || o.slam.prediction.enabled;
  return o;
}

}  // namespace

Mission::Mission(const World& world, const slam::Pose2& start, const MissionOptions& options)
    : world_(world),
      options_(checked(options)),
      start_(start),
      robot_(world, start, options.robot),
      laser_(world, options.laser),
      odometry_(start, options.odometry),
      truth_map_(options.slam.grid),
      reachable_(reachable_free_area(world, {start.x, start.y}, options.robot.radius)),
      meter_(world, reachable_),
      frontiers_(options.frontiers),
      blacklist_(options.blacklist),
      replan_failures_(options.blacklist),
      stuck_clock_({options.stuck_time, false, options.detour_progress}),
      strategy_(
          make_strategy(options.strategy, options.utility_lambda, options.lookahead.skip_share, options.rate_offset)),
      // A spot is the same target within 1 m (the goal shifts as the map grows, as kSameGoalRadius).
      predicted_targets_({kSameGoalRadius, options.lookahead.repredict_after,
                          options.lookahead.predictor.surroundings_diameter, options.lookahead.repredict_growth}),
      recoveries_(make_recoveries(parse_recovery_order(options_.recovery_order))) {
  if (!reachable_.start_valid) check_start(world, world.source(), start, options.robot.radius);
  if (!reachable_.start_valid) {
    throw std::invalid_argument("world " + world.source() + ": the start pose (" + std::to_string(start.x) + ", " +
                                std::to_string(start.y) + ") has no free space around it");
  }
  if (options_.lookahead.enabled) {
    lookahead_ = std::make_unique<LookaheadMapping>(options_.lookahead, world_, options_.slam.grid,
                                                    observable_cells(world_, reachable_));
  }
  if (options_.pose_source == PoseSource::kSlam) rbpf_ = std::make_unique<slam::Rbpf>(options_.slam);
  last_refresh_pose_ = start;
}

Mission::~Mission() = default;

void Mission::record_log(const std::string& path) {
  log_ = open_run_log(path, options_.laser);  // CARMEN log, or a ROS1 bag for a .bag path
}

const slam::OccupancyGrid& Mission::map() const {
  return rbpf_ && !rbpf_->particles().empty() ? rbpf_->particles()[rbpf_->best_particle()].map : truth_map_;
}

slam::Pose2 Mission::estimate() const {
  return rbpf_ && !rbpf_->particles().empty() ? rbpf_->current_pose() : robot_.pose();
}

MissionStatus Mission::step() {
  if (status_ != MissionStatus::kRunning) return status_;
  sense();               // laser and odometry into the map
  deliver_prediction();  // a finished hypothesis joins the look-ahead map and the filter
  refresh();             // costmap, frontiers and the current path, after a map update
  decide();              // a new target when the old one is reached, explored, blocked or stuck
  predict_while_idle();  // opt-in: the idle predictor looks ahead of frontiers not chosen yet
  act();                 // pure pursuit -> unicycle in the true world
  record();              // coverage, paths
  check_end();
  return status_;
}

MissionStatus Mission::run(const std::function<void(const Mission&)>& every_second) {
  double next_call = 0.0;
  while (step() == MissionStatus::kRunning) {
    if (every_second && time_ >= next_call) {
      every_second(*this);
      next_call += 1.0;
    }
  }
  if (every_second) every_second(*this);
  return status_;
}

void Mission::sense() {
  time_ += options_.laser.period();
  slam::LaserScan scan = laser_.scan(robot_.pose(), time_);
  scan.odometry = odometry_.pose();
  ++stats_.scans;
  last_scan_ = scan;
  if (log_) {
    log_->odometry(scan.odometry, 0.0, 0.0, time_);
    log_->scan(scan);
  }
  // Explored means observed: coverage reads the cells the laser saw from where the robot
  // truly was. Read off the SLAM map instead, a map stretched a few decimetres along a
  // corridor (the scan matcher cannot fix position along it) would lose the cells at its
  // ends that the robot saw; how well the SLAM map agrees with the world is measured
  // apart (map_precision, map_recall, slam_position_error).
  slam::insert_scan(truth_map_, robot_.pose(), scan, options_.slam.insert);
  if (rbpf_) {
    map_changed_ = rbpf_->add_scan(scan);
    if (map_changed_) sensed_.add(estimate());
    return;
  }
  sensed_.add(robot_.pose());
  // The map grows every scan; the costmap and frontiers follow at the filter's pace.
  const slam::Pose2 moved = last_refresh_pose_.between(robot_.pose());
  map_changed_ = time_ <= options_.laser.period() + 1e-9 || moved.norm() >= options_.slam.linear_update ||
                 std::abs(moved.theta) >= options_.slam.angular_update;
}

void Mission::deliver_prediction() {
  if (!lookahead_) return;
  std::shared_ptr<const slam::HypothesisMap> h = lookahead_->deliver(time_);
  if (!h) return;
  if (rbpf_) rbpf_->add_hypothesis(std::move(h));  // ignored unless prediction is on
}

SkipRule Mission::skip_rule() const {
  SkipRule rule = options_.lookahead.skip_rule();
  rule.free = options_.free_threshold;  // undecided cells, for wall slivers: as the frontier detector reads them
  // A wall gap closes a region because the robot cannot pass it; an opening the robot fits
  // through is a way on. A gap wider than the robot's diameter would close real doors into
  // wall slivers, so the configured gap is capped at the diameter.
  rule.wall_gap = std::min(rule.wall_gap, 2 * options_.robot.radius);
  if (options_.lookahead.known_boundary) {
    // The simulator's world is the building: its extent is the boundary the paper's Fig. 7(d)
    // assumes known (for the maze, the outside of its outer wall).
    const Eigen::Vector2d lo = world_.origin();
    rule.boundary = SkipRule::Extent{lo.x(), lo.y(), lo.x() + world_.width() * world_.resolution(),
                                     lo.y() + world_.height() * world_.resolution()};
  }
  return rule;
}

std::vector<std::pair<double, double>> Mission::prediction_targets(double goal_x, double goal_y) {
  const std::vector<FrontierCluster> clusters = frontiers_.clusters(map());
  const TargetList targets = selection_targets(clusters, goal_x, goal_y, straight_line_from(estimate()),
                                               options_.lookahead.targets_per_selection);
  for (const auto& [x, y] : targets) predicted_targets_.add(map(), x, y, time_);
  return targets;
}

void Mission::predict_while_idle() {
  if (!lookahead_ || !options_.lookahead.predict_while_idle || !goal_ || !lookahead_->idle()) return;
  if (time_ < next_idle_prediction_) return;
  next_idle_prediction_ = time_ + options_.lookahead.latency;  // clusters() is not free
  const slam::OccupancyGrid& m = map();
  const std::vector<FrontierCluster> clusters = frontiers_.clusters(m);
  const TargetList targets = unpredicted_frontier_targets(
      clusters, m, lookahead_->predicted(), skip_rule(), options_.lookahead.skip_share, predicted_targets_, time_,
      straight_line_from(estimate()), options_.lookahead.targets_per_selection);
  if (targets.empty()) return;
  for (const auto& [x, y] : targets) predicted_targets_.add(m, x, y, time_);
  lookahead_->request(m, targets, time_);
}

void Mission::refresh() {
  // A robot held by the reactive stop neither moves nor turns, so the map-change rule
  // alone would never bring the costmap up to date with what the laser sees ahead.
  if (!map_changed_ && !stop_.holding()) return;
  last_refresh_pose_ = robot_.pose();
  ++stats_.map_refreshes;
  const slam::OccupancyGrid& m = map();
  // After resampling or a change of best particle the map may differ anywhere.
  const std::size_t resamplings = rbpf_ ? rbpf_->statistics().resamplings : 0;
  const std::size_t best = rbpf_ ? rbpf_->best_particle() : 0;
  if (resamplings != last_resamplings_ || best != last_best_ || stats_.map_refreshes == 1) {
    frontiers_.rebuild(m);
    costmap_ = planner::Costmap(m, options_.planner.costmap);
  } else if (!sensed_.empty()) {
    // Only the scans since the last refresh changed the map: within the sensor's range
    // (and a metre of slack) of the poses they were taken from.
    const double r = options_.laser.max_range + 1.0;
    const slam::CellIndex lo = m.cell_at(sensed_.lo.x - r, sensed_.lo.y - r);
    const slam::CellIndex hi = m.cell_at(sensed_.hi.x + r, sensed_.hi.y + r);
    frontiers_.update(m, lo, hi);
    costmap_.update(m, lo, hi);
  }
  sensed_ = {};
  last_resamplings_ = resamplings;
  last_best_ = best;
  if (reached_goal_) {
    stats_.retired_frontier_cells += frontiers_.retire_near(m, reached_goal_->x, reached_goal_->y, kRetireRadius);
    reached_goal_.reset();
  }
  // A backtrack follows the robot's own trail, which the margin may have closed: that is
  // why it is taken. The reactive stop still guards it.
  using Clearance = planner::PathFollower::Clearance;
  const Clearance clearance = kept_on_body_ ? Clearance::kBody : Clearance::kPlanning;
  if (follower_ && !backtracking_ && !squeezing_ && !follower_->path_still_valid(costmap_, clearance)) {
    // New walls block the path: replan from here (to the same goal). A path the margin
    // closed but the body still fits stays at hand for the replan to compare with.
    blocked_rest_ = follower_->remaining_length();
    if (!kept_on_body_ && follower_->path_still_valid(costmap_, Clearance::kBody))
      margin_blocked_ = std::move(follower_);
    follower_.reset();
    path_blocked_ = true;
    ++stats_.replans;
  }
}

bool Mission::goal_still_useful() const {
  if (!goal_) return false;
  if (backtracking_) return true;  // the way out, not a frontier
  // The goal served its frontier while a frontier cell is still near it.
  const slam::OccupancyGrid& m = map();
  const slam::CellIndex g = m.cell_at(goal_->x, goal_->y);
  const int r = static_cast<int>(std::ceil(1.0 / m.resolution()));
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (frontiers_.cells().count({g.x + dx, g.y + dy})) return true;
  return false;
}

bool Mission::goal_predicted() const {
  // Look-ahead mapping: a hypothesis delivered on the way (requested for this very target,
  // so it arrives after the choice) may cover the frontier the robot is driving to. The
  // strategy would skip it now; driving on would map what is already predicted.
  // A goal chosen because every frontier left was predicted is there to observe it.
  if (!lookahead_ || !goal_ || strategy_->prediction_use() != PredictionUse::kSkip || visiting_predicted_) return false;
  const slam::OccupancyGrid& m = map();
  const auto covered = [&](const FrontierCluster& f) {
    return lookahead_->predicted().covered_share(m, f, skip_rule()) >= options_.lookahead.skip_share;
  };
  if (!goal_serves_only_predicted(frontiers_.clusters(m), goal_->x, goal_->y, kSameGoalRadius, covered)) return false;
  spdlog::debug("t {:.1f}: goal ({:.2f}, {:.2f}) dropped: predicted on the way", time_, goal_->x, goal_->y);
  return true;
}

SelectionInputs Mission::selection_inputs() {
  SelectionInputs in{&map(),
                     &costmap_,
                     &frontiers_,
                     strategy_.get(),
                     &blacklist_,
                     estimate(),
                     time_,
                     options_.laser.max_range,
                     options_.max_goal_attempts,
                     options_.planner};
  in.planner.seed = static_cast<std::uint32_t>(options_.planner.seed + static_cast<std::uint32_t>(stats_.plans));
  in.robot_radius = options_.robot.radius;
  if (lookahead_) {
    in.predicted = &lookahead_->predicted();
    in.skip = skip_rule();
  }
  return in;
}

void Mission::count(const Selection& s) {
  stats_.plans += s.plans;
  stats_.plan_failures += s.plan_failures;
  stats_.grid_fallbacks += s.grid_fallbacks;
  stats_.planning_time += s.planning_time;
}

void Mission::act() {
  if (status_ != MissionStatus::kRunning) return;
  planner::VelocityCommand cmd;
  if (!follower_) stop_.clear();
  if (turned_ < options_.initial_turn) {
    cmd.omega = options_.robot.max_turn_rate;  // look around before choosing a target
  } else if (follower_ && escape_.active()) {
    cmd = escape_.command(last_scan_, estimate(), escape_limits());
  } else if (follower_) {
    cmd = follower_->command(estimate());
    const StopGeometry stop{options_.robot.radius, options_.stop_distance, options_.laser.period(), tight_};
    if (cmd.v > 0 && ReactiveStop::blocks(last_scan_, cmd, stop)) {
      cmd.v = 0.0;  // turn on the spot only; the costmap catches up at the next refresh
      ++stats_.safety_stops;
      hold_at_stop();
    } else {
      stop_.clear();
    }
  }
  const slam::Pose2 before = robot_.pose();
  const StepResult r = robot_.step(cmd.v, cmd.omega, options_.laser.period());
  odometry_.update(before.between(r.pose));
  // Retraced crumbs were popped; dropping them again would lead the next backtrack back in.
  if (!backtracking_) {
    const slam::Pose2 p = estimate();
    crumbs_.drop({p.x, p.y});
  }
  path_length_ += r.distance;
  turned_ += std::abs(r.turned);
  if (r.collided) {
    ++stats_.collisions;
    status_ = MissionStatus::kCollision;
  }
}

void Mission::hold_at_stop() {
  // A hold that outlasts a map refresh may be a corner pinning the body: turn and creep out.
  if (stop_.escape_due() && escape_.start(last_scan_, estimate(), escape_limits())) {
    ++stats_.stop_escapes;
    escape_spots_.push_back({estimate().x, estimate().y});
  }
  // A stop that lasts gives the path up: the navigation replans (Follow -> Replan).
  if (stop_.hold(backtracking_ || squeezing_)) {
    if (follower_) blocked_rest_ = follower_->remaining_length();
    follower_.reset();
    path_blocked_ = true;
    ++stats_.replans;
  }
}

EscapeLimits Mission::escape_limits() const {
  return {options_.robot.radius, options_.robot.max_speed, options_.robot.max_turn_rate, options_.laser.period()};
}

void Mission::record() {
  if (stats_.scans % 5 == 1) {
    true_path_.push_back(robot_.pose());
    estimated_path_.push_back(estimate());
  }
  if (time_ >= next_metrics_) {
    next_metrics_ = time_ + options_.metrics_period;
    const double explored = meter_.coverage(truth_map_);
    double with_predictions = explored;
    if (lookahead_) {
      // "Explored or correctly predicted": predicted free cells count where the world is
      // free. A measure of look-ahead mapping only; no end condition reads it.
      const PredictedMap& pm = lookahead_->predicted();
      const double occupied = options_.lookahead.predictor.features.occupied_threshold;
      with_predictions = meter_.coverage(truth_map_, [&](double x, double y) {
        const slam::CellIndex c = pm.cells().cell_at(x, y);
        return pm.predicted(map(), c) && pm.cells().probability(c) < occupied && !world_.is_occupied(x, y);
      });
    }
    curve_.push_back({time_, path_length_, explored, with_predictions});
  }
}

void Mission::check_end() {
  if (status_ != MissionStatus::kRunning) return;
  // The goal is explored space: a prediction counts once the robot has observed it.
  if (coverage() >= options_.coverage_goal)
    status_ = MissionStatus::kCoverageReached;
  else if (time_ >= options_.time_limit)
    status_ = MissionStatus::kTimeLimit;
}

}  // namespace lookahead::exploration
