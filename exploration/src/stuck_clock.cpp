// SPDX-License-Identifier: MIT
#include "lookahead/exploration/stuck_clock.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::exploration {
namespace {

// The clock restarts when the robot gets this much closer to its goal [m].
constexpr double kProgressStep = 0.2;

// A detour: more path left than this [m] and than this many times the straight distance to
// the goal. In doors the margin flickers on, the replanned paths stay 1-5 m long, and their
// random shortening is no progress: counting it would keep the robot at such a door. A ring
// corridor to a hall, by contrast, leaves tens of metres of path to a goal a third as far
// away in a straight line.
constexpr double kDetourPath = 10.0;
constexpr double kDetourRatio = 2.0;

}  // namespace

void StuckClock::start(double now, double distance, double path_left, double driven) {
  best_distance_ = distance;
  best_path_left_ = path_left;
  progress_time_ = now;
  progress_driven_ = driven;
}

bool StuckClock::stuck(double now, double distance, double path_left, double driven) {
  const bool detour = path_left > kDetourPath && path_left > kDetourRatio * distance;
  const bool by_path = options_.along_path || (options_.on_detours && detour);
  const bool closer = distance < best_distance_ - kProgressStep;
  const bool shorter = by_path && path_left < best_path_left_ - kProgressStep;
  if (closer || shorter) {
    best_distance_ = std::min(distance, best_distance_);
    best_path_left_ = std::min(path_left, best_path_left_);
    progress_time_ = now;
    progress_driven_ = driven;
  }
  return now - progress_time_ > options_.stuck_time;
}

}  // namespace lookahead::exploration
