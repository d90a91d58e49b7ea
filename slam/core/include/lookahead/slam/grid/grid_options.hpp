// SPDX-License-Identifier: MIT
// Parameters of the log-odds occupancy grid. Defaults are the documented ones
// (config/slam/default.yaml mirrors them; `lookahead config --dump` prints them).
#pragma once

namespace lookahead::slam {

struct GridOptions {
  double resolution = 0.05;     ///< cell side [m], 0.01..1
  double log_odds_hit = 0.85;   ///< added to a cell a beam ends in (p = 0.70), > 0
  double log_odds_miss = -0.4;  ///< added to a cell a beam passes through (p = 0.40), < 0
  double log_odds_min = -2.0;   ///< clamp, keeps cells able to change (p = 0.12)
  double log_odds_max = 3.5;    ///< clamp (p = 0.97)
  /// A cell becomes an obstacle of the likelihood field when its log-odds reaches this...
  double obstacle_on = 0.5;
  /// ...and stops being one when it falls to this (hysteresis: grazing beams do not make a
  /// wall flicker, which would churn the distance field).
  double obstacle_off = 0.0;
  /// Distances to the nearest obstacle are kept up to this radius [m] (<= 15 cells).
  double distance_field_radius = 0.3;
};

}  // namespace lookahead::slam
