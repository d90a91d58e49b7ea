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

// A forced detour: the replan is longer than this many times the blocked path's rest, plus
// the slack [m]. Walls seen on the way into a room the path crossed unknown space to reach
// leave only the way round through its door, which leads away from the goal; a swap between
// two similar routes is no such detour and keeps the clock running.
constexpr double kForcedDetourRatio = 1.2;
constexpr double kForcedDetourSlack = 1.0;
// Restarts per goal: a goal that keeps sending the robot round is still given up in time.
constexpr int kMaxForcedDetours = 2;

}  // namespace

void StuckClock::start(double now, double distance, double path_left, double driven) {
  detours_ = 0;
  forced_ = false;
  progress_ = {distance, path_left, now, driven};
}

StuckClock::Replan StuckClock::replanned(double now, double distance, double path_left, double blocked_rest,
                                         double driven) {
  if (path_left > kForcedDetourRatio * blocked_rest + kForcedDetourSlack && detours_ < kMaxForcedDetours) {
    if (!forced_) before_detour_ = progress_;
    ++detours_;
    forced_ = true;
    progress_ = {distance, path_left, now, driven};
    return Replan::kForcedDetour;
  }
  // The short way is back: the door closed by the margin alone, and a robot swapping between
  // the two ways is measured as if it had never left the first.
  if (forced_ && kForcedDetourRatio * path_left + kForcedDetourSlack < blocked_rest) {
    forced_ = false;
    progress_ = before_detour_;
    return Replan::kWayBackOpened;
  }
  return Replan::kSameWay;
}

bool StuckClock::stuck(double now, double distance, double path_left, double driven) {
  const bool detour = path_left > kDetourPath && path_left > kDetourRatio * distance;
  const bool by_path = options_.along_path || forced_ || (options_.on_detours && detour);
  const bool closer = distance < progress_.best_distance - kProgressStep;
  const bool shorter = by_path && path_left < progress_.best_path_left - kProgressStep;
  if (closer || shorter) {
    progress_.best_distance = std::min(distance, progress_.best_distance);
    progress_.best_path_left = std::min(path_left, progress_.best_path_left);
    progress_.time = now;
    progress_.driven = driven;
  }
  return now - progress_.time > options_.stuck_time;
}

}  // namespace lookahead::exploration
