// SPDX-License-Identifier: MIT
#include "lookahead/exploration/generated_worlds.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace lookahead::exploration {
namespace {

void require(bool ok, const char* field, double value, const char* why) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + " = " + std::to_string(value) + ": " + why);
  }
}

int cells(double metres, double resolution) { return static_cast<int>(std::lround(metres / resolution)); }

}  // namespace

void OfficeOptions::validate() const {
  require(rooms_per_side >= 1 && rooms_per_side <= 100, "rooms_per_side", rooms_per_side, "1..100");
  require(resolution > 0, "resolution", resolution, "must be > 0");
  require(door_width > 0, "door_width", door_width, "must be > 0");
  require(room_width > door_width + 0.2, "room_width", room_width, "must exceed door_width + 0.2 m");
  require(room_depth > 0, "room_depth", room_depth, "must be > 0");
  require(corridor_width > 0, "corridor_width", corridor_width, "must be > 0");
  require(wall_thickness >= resolution, "wall_thickness", wall_thickness, "must be >= resolution");
}

double OfficeOptions::width_m() const { return rooms_per_side * room_width + (rooms_per_side + 1) * wall_thickness; }

double OfficeOptions::height_m() const { return 2.0 * room_depth + corridor_width + 4.0 * wall_thickness; }

// Layout from the bottom: wall, lower rooms, wall, corridor, wall, upper rooms, wall. The
// floor starts solid and rooms, corridor and doors are carved out of it.
GeneratedWorld make_office(const OfficeOptions& o) {
  o.validate();
  const double t = o.wall_thickness;
  World w(cells(o.width_m(), o.resolution), cells(o.height_m(), o.resolution), o.resolution, {0.0, 0.0},
          World::kOccupied);
  const double corridor_lo = t + o.room_depth + t;
  const double corridor_hi = corridor_lo + o.corridor_width;
  w.fill_rect({t, corridor_lo}, {o.width_m() - t, corridor_hi}, World::kFree);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> door_at(0.1, o.room_width - o.door_width - 0.1);
  for (int side = 0; side < 2; ++side) {
    const double room_lo = side == 0 ? t : corridor_hi + t;
    const double wall_lo = side == 0 ? room_lo + o.room_depth : corridor_hi;
    for (int i = 0; i < o.rooms_per_side; ++i) {
      const double x0 = t + i * (o.room_width + t);
      w.fill_rect({x0, room_lo}, {x0 + o.room_width, room_lo + o.room_depth}, World::kFree);
      const double d = x0 + door_at(rng);
      w.fill_rect({d, wall_lo}, {d + o.door_width, wall_lo + t}, World::kFree);
    }
  }
  w.set_source("generated office: " + std::to_string(o.rooms_per_side) + " rooms a side, seed " +
               std::to_string(o.seed));
  return {std::move(w), {o.width_m() / 2.0, 0.5 * (corridor_lo + corridor_hi), 0.0}};
}

void MazeOptions::validate() const {
  require(resolution > 0, "resolution", resolution, "must be > 0");
  require(block > 0, "block", block, "must be > 0");
  require(corridor > 0, "corridor", corridor, "must be > 0");
  require(wall_thickness >= resolution, "wall_thickness", wall_thickness, "must be >= resolution");
  const double n = (side - corridor) / (block + corridor);
  require(n >= 1 && std::abs(n - std::round(n)) < 1e-6, "side", side,
          "must equal n * block + (n + 1) * corridor for a whole n >= 1");
}

int MazeOptions::blocks_per_side() const {
  return static_cast<int>(std::lround((side - corridor) / (block + corridor)));
}

GeneratedWorld make_pslam_maze(const MazeOptions& o) {
  o.validate();
  const double t = o.wall_thickness;
  const int outer = cells(o.side + 2.0 * t, o.resolution);
  World w(outer, outer, o.resolution, {-t, -t}, World::kOccupied);
  w.fill_rect({0.0, 0.0}, {o.side, o.side}, World::kFree);
  const int n = o.blocks_per_side();
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector2d lo(o.corridor + i * (o.block + o.corridor), o.corridor + j * (o.block + o.corridor));
      w.fill_rect(lo, lo + Eigen::Vector2d(o.block, o.block), World::kOccupied);
    }
  }
  w.set_source("generated P-SLAM square maze: " + std::to_string(n) + " x " + std::to_string(n) + " blocks");
  return {std::move(w), {o.corridor / 2.0, o.corridor / 2.0, 0.0}};
}

void CorridorOptions::validate() const {
  require(resolution > 0, "resolution", resolution, "must be > 0");
  require(width > box_depth + 1.0, "width", width, "must exceed box_depth + 1 m (the robot passes a box)");
  require(leg_ab > width, "leg_ab", leg_ab, "must exceed width");
  require(leg_bc > width, "leg_bc", leg_bc, "must exceed width");
  require(box_length > 0, "box_length", box_length, "must be > 0");
  require(box_depth > 0, "box_depth", box_depth, "must be > 0");
  require(box_spacing > box_length, "box_spacing", box_spacing, "must exceed box_length");
  require(box_jitter >= 0 && box_jitter < 0.5 * (box_spacing - box_length), "box_jitter", box_jitter,
          "must be in [0, (box_spacing - box_length) / 2)");
  require(wall_thickness >= resolution, "wall_thickness", wall_thickness, "must be >= resolution");
}

// Leg A-B runs along +x over y in [0, width]; leg B-C runs along +y over x in
// [leg_ab, leg_ab + width]. Boxes start one spacing from each leg's start and alternate
// between the two walls of their leg; none is placed in the corner square B.
GeneratedWorld make_pslam_corridor(const CorridorOptions& o) {
  o.validate();
  const double t = o.wall_thickness;
  const double w_m = o.leg_ab + o.width + 2 * t;
  const double h_m = o.leg_bc + o.width + 2 * t;
  World w(cells(w_m, o.resolution), cells(h_m, o.resolution), o.resolution, {-t, -t}, World::kOccupied);
  w.fill_rect({0.0, 0.0}, {o.leg_ab + o.width, o.width}, World::kFree);
  w.fill_rect({o.leg_ab, 0.0}, {o.leg_ab + o.width, o.leg_bc + o.width}, World::kFree);
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> jitter(-o.box_jitter, o.box_jitter);
  int side = 0;
  for (double s = o.box_spacing; s + o.box_length < o.leg_ab - 0.5; s += o.box_spacing, side ^= 1) {
    const double x = s + jitter(rng);
    const double y0 = side == 0 ? 0.0 : o.width - o.box_depth;
    w.fill_rect({x, y0}, {x + o.box_length, y0 + o.box_depth}, World::kOccupied);
  }
  for (double s = o.width + o.box_spacing; s + o.box_length < o.leg_bc + o.width - 0.5; s += o.box_spacing, side ^= 1) {
    const double y = s + jitter(rng);
    const double x0 = side == 0 ? o.leg_ab : o.leg_ab + o.width - o.box_depth;
    w.fill_rect({x0, y}, {x0 + o.box_depth, y + o.box_length}, World::kOccupied);
  }
  w.set_source("generated P-SLAM L corridor with boxes: legs " + std::to_string(o.leg_ab) + " m and " +
               std::to_string(o.leg_bc) + " m, seed " + std::to_string(o.seed));
  return {std::move(w), {0.8, 0.5 * o.width, 0.0}};
}

}  // namespace lookahead::exploration
