// SPDX-License-Identifier: MIT
// The garage is a list of solid boxes and two sloped slabs, rasterised into voxels.
#include <cmath>
#include <random>

#include "lookahead/slam/sim3d/world3d.hpp"

namespace lookahead::slam {
namespace {

constexpr double kLength = 84.0, kWidth = 36.0;  // footprint [m]
constexpr double kDeck = 3.3;                    // height of the upper deck [m]
constexpr double kRoof = 6.6;
constexpr double kSlab = 0.2;  // slab and wall thickness [m]
// The ramps run along x in [kRampX0, kRampX1]: up at y in [14, 18], down at y in [18, 22].
constexpr double kRampX0 = 30.0, kRampX1 = 54.0, kRampY0 = 14.0, kRampY1 = 22.0;

struct Box {
  Eigen::Vector3d lo, hi;
};

class Rasteriser {
 public:
  explicit Rasteriser(EvidenceOctree& map) : map_(map), writer_(map) {}
  void box(const Box& b) {
    const OctreeGrid& g = map_.grid();
    for (long z = g.axis_key(b.lo.z()); z <= g.axis_key(b.hi.z() - 1e-9); ++z)
      for (long y = g.axis_key(b.lo.y()); y <= g.axis_key(b.hi.y() - 1e-9); ++y)
        for (long x = g.axis_key(b.lo.x()); x <= g.axis_key(b.hi.x() - 1e-9); ++x) solid(x, y, z);
  }
  /// A slab whose top rises linearly from z0 at x0 to z1 at x1, over y in [y0, y1].
  void ramp(double x0, double x1, double y0, double y1, double z0, double z1) {
    const OctreeGrid& g = map_.grid();
    for (long x = g.axis_key(x0); x <= g.axis_key(x1 - 1e-9); ++x) {
      const double top = z0 + (z1 - z0) * (g.axis_centre(static_cast<int>(x)) - x0) / (x1 - x0);
      for (long z = g.axis_key(top - kSlab); z <= g.axis_key(top - 1e-9); ++z)
        for (long y = g.axis_key(y0); y <= g.axis_key(y1 - 1e-9); ++y) solid(x, y, z);
    }
  }

 private:
  void solid(long x, long y, long z) {
    writer_.set_log_odds({static_cast<std::uint16_t>(x), static_cast<std::uint16_t>(y), static_cast<std::uint16_t>(z)},
                         static_cast<float>(map_.options().log_odds_max));
  }
  EvidenceOctree& map_;
  OctreeWriter writer_;
};

void add_structure(Rasteriser& r) {
  const double t = kSlab;
  r.box({{0, 0, -t}, {kLength, kWidth, 0}});             // ground floor
  r.box({{0, 0, kRoof}, {kLength, kWidth, kRoof + t}});  // roof
  // Upper deck, with the opening the ramps come through.
  r.box({{0, 0, kDeck - t}, {kLength, kRampY0, kDeck}});
  r.box({{0, kRampY1, kDeck - t}, {kLength, kWidth, kDeck}});
  r.box({{0, kRampY0, kDeck - t}, {kRampX0, kRampY1, kDeck}});
  r.box({{kRampX1, kRampY0, kDeck - t}, {kLength, kRampY1, kDeck}});
  r.ramp(kRampX0, kRampX1, kRampY0, 18.0, 0.0, kDeck);  // up, eastwards
  r.ramp(kRampX0, kRampX1, 18.0, kRampY1, 0.0, kDeck);  // down, westwards
  r.box({{kRampX0, 17.9, 0}, {kRampX1, 18.1, kRoof}});  // wall between the ramps
  // Outer walls.
  r.box({{0, 0, 0}, {kLength, t, kRoof}});
  r.box({{0, kWidth - t, 0}, {kLength, kWidth, kRoof}});
  r.box({{0, 0, 0}, {t, kWidth, kRoof}});
  r.box({{kLength - t, 0, 0}, {kLength, kWidth, kRoof}});
  // Columns between the aisles and the parking rows.
  for (double x = 2.0; x < kLength; x += 8.4)
    for (double y : {12.0, 24.0}) r.box({{x - 0.3, y - 0.3, 0}, {x + 0.3, y + 0.3, kRoof}});
}

// Cars in the parking rows, each bay filled with probability 0.6 (the seeded part).
void add_cars(Rasteriser& r, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution parked(0.6);
  const double rows[] = {0.4, 10.2, 22.2, 32.2};  // lower y of each row; cars are 3.6 m long
  const double crossings[] = {8.0, 20.0, 63.0};   // x of the route's cross-aisle legs
  for (double floor : {0.0, kDeck}) {
    for (double y0 : rows) {
      for (double x = 1.5; x + 1.8 < kLength - 0.5; x += 2.6) {
        const double centre = x + 0.9;
        const double from_column = std::fmod(centre - 2.0 + 84.0, 8.4);  // columns at 2 + 8.4 i
        bool blocked = from_column < 1.5 || from_column > 6.9;
        for (double c : crossings) blocked = blocked || std::abs(centre - c) < 3.0;
        if (blocked || !parked(rng)) continue;
        r.box({{x, y0, floor}, {x + 1.8, y0 + 3.6, floor + 1.4}});
      }
    }
  }
}

}  // namespace

World3 make_garage_world(std::uint64_t seed, double resolution) {
  OctreeOptions o;
  o.resolution = resolution;
  World3 w{"garage", EvidenceOctree(o), {}};
  Rasteriser r(w.map);
  add_structure(r);
  add_cars(r, seed);
  const double d = kDeck;
  w.route = {{8, 7, 0}, {20, 7, 0}, {20, 16, 0}, {30, 16, 0}, {54, 16, d}, {63, 16, d}, {63, 29, d}, {8, 29, d},
             {8, 7, d}, {63, 7, d}, {63, 20, d}, {54, 20, d}, {30, 20, 0}, {20, 20, 0}, {20, 9, 0},  {8, 7.5, 0}};
  return w;
}

}  // namespace lookahead::slam
