// SPDX-License-Identifier: MIT
#include "lookahead/exploration/world_source.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "lookahead/exploration/robot.hpp"
#include "lookahead/exploration/world_loader.hpp"
#include "lookahead/exploration/world_reachability.hpp"

namespace lookahead::exploration {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

World load_file(const WorldSpec& spec) {
  if (ends_with(spec.name, ".yaml") || ends_with(spec.name, ".yml")) return load_map_yaml(spec.name);
  if (ends_with(spec.name, ".world")) return load_stage_world(spec.name);
  // An image carries no scale: a guessed one would shrink or stretch every room.
  if (!(spec.image_resolution > 0)) {
    throw std::invalid_argument(spec.name +
                                ": resolution (m/pixel) of an image world must be stated (--resolution, "
                                "or resolution: in a study), got " +
                                std::to_string(spec.image_resolution));
  }
  ImageWorldOptions o;
  o.resolution = spec.image_resolution;
  if (spec.pixel_rule == "only_white")
    o.rule = PixelRule::only_white();
  else if (spec.pixel_rule != "stage") {
    throw std::invalid_argument("pixel rule '" + spec.pixel_rule + "' (choose stage or only_white)");
  }
  return load_image_world(spec.name, o);
}

}  // namespace

void check_start(const World& world, const std::string& name, const slam::Pose2& start, double robot_radius) {
  const std::string pose =
      "(" + std::to_string(start.x) + ", " + std::to_string(start.y) + ", " + std::to_string(start.theta) + ")";
  const Eigen::Vector2d lo = world.origin();
  const Eigen::Vector2d hi = lo + Eigen::Vector2d(world.width_m(), world.height_m());
  if (!(std::isfinite(start.x) && std::isfinite(start.y) && std::isfinite(start.theta))) {
    throw std::invalid_argument("world " + name + ": the start pose " + pose + " is not finite");
  }
  if (start.x < lo.x() || start.y < lo.y() || start.x >= hi.x() || start.y >= hi.y()) {
    throw std::invalid_argument("world " + name + ": the start pose " + pose + " is outside the map, which spans (" +
                                std::to_string(lo.x()) + ", " + std::to_string(lo.y()) + ") to (" +
                                std::to_string(hi.x()) + ", " + std::to_string(hi.y()) + ")");
  }
  if (disc_collides(world, {start.x, start.y}, robot_radius)) {
    throw std::invalid_argument("world " + name + ": the start pose " + pose + " is in collision (a wall within the " +
                                std::to_string(robot_radius) + " m robot radius)");
  }
}

slam::Pose2 default_start(const World& world, double clearance) {
  // The middle of the free space, not of the raster: Stage line drawings leave free space
  // outside the building too, but most of the free area is inside.
  double mx = 0, my = 0, n = 0;
  for (int y = 0; y < world.height(); y += 4)
    for (int x = 0; x < world.width(); x += 4)
      if (!world.is_occupied(slam::CellIndex{x, y})) {
        const Eigen::Vector2d c = world.center_of({x, y});
        mx += c.x();
        my += c.y();
        n += 1;
      }
  if (n == 0) throw std::invalid_argument(world.source() + ": the world has no free space");
  mx /= n;
  my /= n;
  std::vector<std::pair<double, slam::Pose2>> spots;
  for (double y = world.origin().y(); y < world.origin().y() + world.height_m(); y += 0.25) {
    for (double x = world.origin().x(); x < world.origin().x() + world.width_m(); x += 0.25) {
      if (!disc_collides(world, {x, y}, clearance)) spots.push_back({std::hypot(x - mx, y - my), {x, y, 0.0}});
    }
  }
  if (spots.empty()) throw std::invalid_argument(world.source() + ": no free spot with the clearance for a start");
  std::sort(spots.begin(), spots.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  // The middle may fall in a closet: take the first spot (nearest the middle) whose region
  // holds at least half of the free area, else the spot with the largest region seen.
  const double free_area = world.free_area_m2();
  slam::Pose2 best = spots.front().second;
  double best_area = -1.0;
  for (std::size_t i = 0; i < spots.size() && i < 40; i += (i < 10 ? 1 : 3)) {
    const slam::Pose2& p = spots[i].second;
    const double area = reachable_free_area(world, {p.x, p.y}, clearance / 2).area_m2;
    if (area > best_area) {
      best_area = area;
      best = p;
    }
    if (area >= 0.5 * free_area) break;
  }
  return best;
}

GeneratedWorld load_world(const WorldSpec& spec, double robot_radius) {
  GeneratedWorld g;
  if (spec.name == "office") {
    OfficeOptions o;
    o.seed = spec.seed;
    g = make_office(o);
  } else if (spec.name == "maze") {
    g = make_pslam_maze();
  } else if (spec.name == "corridor") {
    CorridorOptions o;
    o.seed = spec.seed;
    g = make_pslam_corridor(o);
  } else {
    g.world = load_file(spec);
    g.start = default_start(g.world, std::max(0.6, 2 * robot_radius));
  }
  if (spec.start) g.start = *spec.start;
  check_start(g.world, spec.name, g.start, robot_radius);
  return g;
}

}  // namespace lookahead::exploration
