// SPDX-License-Identifier: MIT
#include "lookahead/exploration/target_selection.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "lookahead/exploration/information_gain.hpp"
#include "lookahead/exploration/travel_cost.hpp"

namespace lookahead::exploration {

std::optional<planner::Point2> nearest_free(const planner::Costmap& costmap, const slam::OccupancyGrid& map, double x,
                                            double y, double radius) {
  const slam::CellIndex c = costmap.cell_at({x, y});
  if (costmap.cell_is_free(c)) return planner::Point2{x, y};
  // Breadth-first through the map's open cells, 4-connected so that no step slips between
  // two wall cells touching at a corner; the first free cell reached is the nearest by the
  // walk, the straight-line nearest among that ring. The nearest free cell as the crow
  // flies may lie behind a wall: in a passage the margin closes, a start in the next room
  // sent the robot into the wall beside it for as long as the reactive stop held it.
  const int r = static_cast<int>(std::ceil(radius / costmap.resolution()));
  const double occupied = costmap.options().occupied_threshold;
  const auto open = [&](slam::CellIndex q) { return map.is_known(q) && map.probability(q) < occupied; };
  std::unordered_set<slam::CellIndex, CellHash> seen{c};
  std::vector<slam::CellIndex> ring{c};
  for (int step = 0; step < 2 * r && !ring.empty(); ++step) {
    std::vector<slam::CellIndex> next;
    for (const slam::CellIndex q : ring) {
      for (const slam::CellIndex n : {slam::CellIndex{q.x + 1, q.y}, slam::CellIndex{q.x - 1, q.y},
                                      slam::CellIndex{q.x, q.y + 1}, slam::CellIndex{q.x, q.y - 1}}) {
        if (std::hypot(n.x - c.x, n.y - c.y) > r || !open(n) || !seen.insert(n).second) continue;
        next.push_back(n);
      }
    }
    std::optional<planner::Point2> best;
    double best_d = INFINITY;
    for (const slam::CellIndex q : next) {
      const double d = std::hypot(q.x - c.x, q.y - c.y);
      if (d < best_d && costmap.cell_is_free(q)) {
        best_d = d;
        best = costmap.cell_center(q);
      }
    }
    if (best) return best;
    ring = std::move(next);
  }
  return std::nullopt;
}

namespace {

// No cell within `clearance` of the segment a-b (sampled every quarter cell) is occupied in
// the map itself.
bool segment_clear(const slam::OccupancyGrid& map, planner::Point2 a, planner::Point2 b, double clearance,
                   double threshold) {
  const double res = map.resolution();
  const int r = static_cast<int>(std::ceil(clearance / res));
  const double length = std::hypot(b.x - a.x, b.y - a.y);
  const int steps = std::max(1, static_cast<int>(std::ceil(4.0 * length / res)));
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
    const slam::CellIndex c = map.cell_at(x, y);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const slam::CellIndex q{c.x + dx, c.y + dy};
        double qx, qy;
        map.cell_center(q, qx, qy);
        const bool near = (dx == 0 && dy == 0) || std::hypot(qx - x, qy - y) <= clearance;
        if (near && map.is_known(q) && map.probability(q) >= threshold) return false;
      }
  }
  return true;
}

// Travel costs from `start`; with `targets`, exact only for them (the search stops there).
TravelCost travel_cost(const planner::Costmap& cm, const planner::Point2& start,
                       const std::vector<slam::CellIndex>& targets = {}) {
  const slam::CellIndex lo = cm.origin();
  const slam::CellIndex hi{lo.x + cm.width() - 1, lo.y + cm.height() - 1};
  return TravelCost(
      lo, hi, cm.resolution(), cm.cell_at(start), [&](slam::CellIndex c) { return cm.cell_is_free(c); }, targets);
}

std::vector<slam::CellIndex> goal_cells(const planner::Costmap& cm, const std::vector<FrontierCluster>& clusters) {
  std::vector<slam::CellIndex> cells;
  for (const FrontierCluster& f : clusters)
    if (f.has_goal) cells.push_back(cm.cell_at({f.goal_x, f.goal_y}));
  return cells;
}

// The Dijkstra path, string-pulled: each waypoint is the farthest later cell still in free
// line of sight (the costmap's exact segment check, as the planner's own paths pass).
planner::Path grid_path(const planner::Costmap& cm, const TravelCost& cost, const planner::Point2& start,
                        const planner::Point2& goal) {
  const std::vector<slam::CellIndex> cells = cost.path_to(cm.cell_at(goal));
  planner::Path path{start};
  std::size_t i = 0;
  while (i + 1 < cells.size()) {
    std::size_t j = cells.size() - 1;
    while (j > i + 1 && !cm.segment_is_free(path.back(), cm.cell_center(cells[j]))) --j;
    path.push_back(cm.cell_center(cells[j]));
    i = j;
  }
  if (path.size() > 1) path.back() = goal;
  return cm.path_is_free(path) ? path : planner::Path{};
}

// The Dijkstra price runs between cell centres; the start and the goal may each sit up to
// half a cell diagonal off theirs, so the grid path proves a path this long exists. 5 % on
// top lets the sampler find a way round the other side of an obstacle as well.
double grid_path_bound(const planner::Costmap& cm, double price) {
  return 1.05 * price + std::sqrt(2.0) * cm.resolution();
}

// The information gain of a goal, with the look-ahead map as the strategy uses it.
double goal_gain(const SelectionInputs& in, const FrontierCluster& f) {
  const PredictionUse use = in.predicted ? in.strategy->prediction_use() : PredictionUse::kNone;
  const slam::OccupancyGrid& map = *in.map;
  switch (use) {
    case PredictionUse::kNone:
      return visible_information_gain(map, f.goal_x, f.goal_y, in.sensor_range);
    case PredictionUse::kSkip: {
      const auto known = [&](slam::CellIndex c) { return in.predicted->predicted(map, c); };
      return visible_information_gain(map, f.goal_x, f.goal_y, in.sensor_range, known);
    }
    case PredictionUse::kOccludingGain: {
      const slam::OccupancyGrid& predicted = in.predicted->cells();
      const auto wall = [&](slam::CellIndex c) { return in.predicted->predicted(map, c) && predicted.is_obstacle(c); };
      return visible_information_gain(map, f.goal_x, f.goal_y, in.sensor_range, nullptr, wall);
    }
  }
  return 0.0;
}

bool skips_predicted(const SelectionInputs& in) {
  return in.predicted && in.strategy->prediction_use() == PredictionUse::kSkip;
}

std::vector<Candidate> price(const SelectionInputs& in, const std::vector<FrontierCluster>& clusters,
                             const TravelCost& cost, bool& any_reachable, bool& any_waiting) {
  const planner::Costmap& cm = *in.costmap;
  std::vector<Candidate> out;
  any_reachable = false;
  any_waiting = false;
  for (const FrontierCluster& f : clusters) {
    spdlog::trace("cluster of {} cells at ({:.2f}, {:.2f}): goal {} ({:.2f}, {:.2f}), cost {:.1f} m", f.cells.size(),
                  f.centroid_x, f.centroid_y, f.has_goal, f.goal_x, f.goal_y,
                  f.has_goal ? cost.at(cm.cell_at({f.goal_x, f.goal_y})) : -1.0);
    if (!f.has_goal) continue;
    const double d = cost.at(cm.cell_at({f.goal_x, f.goal_y}));
    if (!std::isfinite(d)) continue;
    any_reachable = true;
    if (in.blacklist->contains(f.goal_x, f.goal_y, in.now)) {
      any_waiting = any_waiting || !in.blacklist->permanent(f.goal_x, f.goal_y);
      continue;
    }
    Candidate c{&f, d, goal_gain(in, f), 0.0};
    if (skips_predicted(in)) c.predicted_share = in.predicted->covered_share(*in.map, f, in.skip);
    out.push_back(c);
  }
  return out;
}

// Debug trace of look-ahead mapping: how much of the chosen frontier's far side was
// already predicted, and how many frontiers the strategy skipped or nearly skipped.
void log_predicted_shares(const SelectionInputs& in, const std::vector<Candidate>& candidates, std::size_t pick) {
  int skipped = 0, partly = 0;
  for (const Candidate& c : candidates) {
    skipped += c.predicted_share >= 1.0;
    partly += c.predicted_share > 0.0 && c.predicted_share < 1.0;
  }
  const Candidate& c = candidates[pick];
  spdlog::debug(
      "look-ahead: chosen frontier of {} cells at ({:.2f}, {:.2f}) {:.0f}% predicted, gain {:.1f} m^2; "
      "{} of {} frontiers fully predicted, {} partly",
      c.cluster->cells.size(), c.cluster->goal_x, c.cluster->goal_y, 100 * c.predicted_share, c.information_gain,
      skipped, candidates.size(), partly);
  if (in.skip.variant != SkipVariant::kRegion || !spdlog::should_log(spdlog::level::debug)) return;
  const RegionArea a = in.predicted->region_area(*in.map, *c.cluster, in.skip);
  spdlog::debug("look-ahead: its region: {:.1f} m^2 predicted, {:.1f} m^2 not", a.predicted, a.unpredicted);
}

// Plans from `start` to the goal with OMPL inside the ellipse the Dijkstra price bounds,
// retries once with more samples, and falls back to the grid path (counted) when the
// sampler misses a passage the price went through.
planner::PlanResult plan_to(const SelectionInputs& in, const TravelCost& cost, const planner::Point2& start,
                            const planner::Point2& goal, Selection& s) {
  const slam::Pose2 from{start.x, start.y, in.pose.theta};
  planner::PlannerOptions options = in.planner;
  options.cost_bound = grid_path_bound(*in.costmap, cost.at(in.costmap->cell_at(goal)));
  planner::PlanResult r = planner::plan(*in.costmap, from, goal.x, goal.y, options);
  ++s.plans;
  s.planning_time += r.planning_time;
  if (r.status == planner::PlanStatus::kNoPath && options.max_samples > 0) {
    // The Dijkstra pricing found a way, so a failure is a narrow passage (a door) that a
    // sample-limited search missed: one more try with four times the samples.
    options.max_samples *= 4;
    options.samples_per_m2 *= 4;
    r = planner::plan(*in.costmap, from, goal.x, goal.y, options);
    ++s.plans;
    s.planning_time += r.planning_time;
  }
  if (!r.solved()) {
    // Deviation from a pure sampling planner: a passage a few cells wide defeats the
    // sampler, while the Dijkstra price already holds a checked way through it.
    r.path = grid_path(*in.costmap, cost, start, goal);
    if (!r.path.empty()) {
      r.status = planner::PlanStatus::kSolved;
      ++s.grid_fallbacks;
    }
  }
  if (r.solved()) {
    s.outcome = SelectionOutcome::kPlanned;
    s.goal_x = goal.x;
    s.goal_y = goal.y;
    s.path = r.path;
    if (start.x != in.pose.x || start.y != in.pose.y) s.path.insert(s.path.begin(), {in.pose.x, in.pose.y});
  }
  return r;
}

}  // namespace

Selection select_target(const SelectionInputs& in) {
  Selection s;
  const std::vector<FrontierCluster> clusters = in.frontiers->clusters(*in.map);
  s.clusters = clusters.size();
  if (std::none_of(clusters.begin(), clusters.end(), [](const FrontierCluster& f) { return f.has_goal; })) {
    return s;  // kNoFrontier
  }
  s.outcome = SelectionOutcome::kUnreachable;
  const auto start = nearest_free(*in.costmap, *in.map, in.pose.x, in.pose.y, 0.5);
  if (!start) return s;
  bool any_reachable = false, any_waiting = false;
  const TravelCost cost = travel_cost(*in.costmap, *start, goal_cells(*in.costmap, clusters));
  std::vector<Candidate> candidates = price(in, clusters, cost, any_reachable, any_waiting);
  s.candidates = candidates.size();
  if (!any_reachable) return s;  // kUnreachable: frontiers only beyond gaps the robot cannot pass
  // Every reachable frontier was tried recently (visited without clearing it, or failed):
  // unreachable for now, and for good once each is blacklisted for good.
  s.outcome = candidates.empty() ? SelectionOutcome::kUnreachable : SelectionOutcome::kPlanFailed;
  s.waiting_on_blacklist = candidates.empty() && any_waiting;
  for (int attempt = 0; attempt < in.max_attempts && !candidates.empty(); ++attempt) {
    auto pick = in.strategy->choose(candidates);
    if (!pick) {
      // Every frontier left is predicted. An unobserved prediction is not a map: the robot
      // visits them, and the time this first happened ends P-SLAM's protocol (sec. V-A.1).
      s.rest_predicted = true;
      pick = in.strategy->choose_any(candidates);
      if (!pick) break;
    }
    const FrontierCluster& target = *candidates[*pick].cluster;
    if (skips_predicted(in)) log_predicted_shares(in, candidates, *pick);
    const planner::PlanResult r = plan_to(in, cost, *start, {target.goal_x, target.goal_y}, s);
    if (r.solved()) return s;
    ++s.plan_failures;
    spdlog::debug("plan to ({:.2f}, {:.2f}) from ({:.2f}, {:.2f}) failed: {} {}", target.goal_x, target.goal_y,
                  start->x, start->y, planner::to_string(r.status), r.message);
    in.blacklist->add(target.goal_x, target.goal_y, in.now);
    candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(*pick));
  }
  return s;
}

Selection replan_to_goal(const SelectionInputs& in, const planner::Point2& goal) {
  Selection s;
  s.outcome = SelectionOutcome::kPlanFailed;
  const auto start = nearest_free(*in.costmap, *in.map, in.pose.x, in.pose.y, 0.5);
  if (!start || !in.costmap->is_free(goal)) return s;
  const TravelCost cost = travel_cost(*in.costmap, *start, {in.costmap->cell_at(goal)});
  if (!cost.reachable(in.costmap->cell_at(goal))) return s;
  plan_to(in, cost, *start, goal, s);
  return s;
}

Selection select_escape(const SelectionInputs& in, Breadcrumbs& crumbs) {
  Selection s;
  s.outcome = SelectionOutcome::kUnreachable;
  const planner::Costmap& cm = *in.costmap;
  const auto start = nearest_free(cm, *in.map, in.pose.x, in.pose.y, 0.5);
  // With no free cell near the robot its place is empty: any free crumb is outside it.
  const std::optional<TravelCost> place = start ? std::optional<TravelCost>(travel_cost(cm, *start)) : std::nullopt;
  const auto outside = [&](planner::Point2 p) { return cm.is_free(p) && !(place && place->reachable(cm.cell_at(p))); };
  // Between passes of the trail the map decides, with the robot's body and no margin: the
  // margin may have closed a door the robot drove through, but a wall between two trails,
  // or a jamb a shortcut would brush, is in the map itself.
  const auto passable = [&](planner::Point2 a, planner::Point2 b) {
    return segment_clear(*in.map, a, b, in.robot_radius, cm.options().occupied_threshold);
  };
  planner::Path path = crumbs.backtrack({in.pose.x, in.pose.y}, outside, passable);
  if (path.size() < 2) return s;
  s.outcome = SelectionOutcome::kPlanned;
  s.goal_x = path.back().x;
  s.goal_y = path.back().y;
  s.path = std::move(path);
  return s;
}

}  // namespace lookahead::exploration
