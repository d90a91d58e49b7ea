// SPDX-License-Identifier: MIT
// Frontier spots the idle predictor tried lately, with how much of their surroundings was
// known then. P-SLAM's registration (sec. III) of surroundings that did not change, against
// a map that barely did, gives the answer it gave before; trying a spot again only once its
// surroundings grew keeps the predictor's work where the map is new.
#pragma once

#include <cstddef>
#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"

namespace lookahead::exploration {

struct PredictionAttemptOptions {
  double same_spot_radius = 1.0;        ///< goals this close are one spot [m]
  double wait = 10.0;                   ///< a spot is tried again no sooner than this [s, simulated]
  double surroundings_diameter = 10.0;  ///< the disc whose known cells are counted [m]
  /// ... and only once the known cells of its surroundings grew by this share (0: always).
  double growth = 0.1;
};

class PredictionAttempts {
 public:
  explicit PredictionAttempts(const PredictionAttemptOptions& options = {}) : options_(options) {}
  /// Remembers a try at (x, y), replacing an earlier one at the same spot.
  void add(const slam::OccupancyGrid& map, double x, double y, double now);
  /// True while the spot's last try is younger than `wait`, or its surroundings have not
  /// grown by `growth` since.
  [[nodiscard]] bool tried_lately(const slam::OccupancyGrid& map, double x, double y, double now) const;
  [[nodiscard]] std::size_t size() const { return attempts_.size(); }

 private:
  struct Attempt {
    double x, y, time;
    std::size_t known_cells;
  };
  [[nodiscard]] const Attempt* find(double x, double y) const;
  [[nodiscard]] std::size_t known_cells(const slam::OccupancyGrid& map, double x, double y) const;

  PredictionAttemptOptions options_;
  std::vector<Attempt> attempts_;
};

}  // namespace lookahead::exploration
