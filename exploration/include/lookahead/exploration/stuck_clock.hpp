// SPDX-License-Identifier: MIT
// When does a robot driving to a goal give it up? When it has made no progress for
// stuck_time. Progress is getting kProgressStep closer to the goal in a straight line; a
// shorter path left counts too always (`along_path`) or only on a detour (`on_detours`:
// more than 10 m of path left, over twice the straight distance), where a ring corridor can
// lead away from the goal for minutes. The best path left is kept across replans, so a robot
// swapping between routes without shortening either is still stuck. One kind of replan
// restarts the clock instead: new walls closing the way and leaving only one much longer
// (a forced detour), the map's news rather than a swap, at most twice per goal. Should the
// short way open again (a door the margin flickered on, not a wall), the restart is undone.
#pragma once

namespace lookahead::exploration {

struct StuckClockOptions {
  double stuck_time = 30.0;  ///< no progress this long: stuck [s]
  bool along_path = false;   ///< a shorter path left is progress, detour or not
  bool on_detours = false;   ///< a shorter path left is progress on a detour
};

class StuckClock {
 public:
  explicit StuckClock(const StuckClockOptions& options = {}) : options_(options) {}

  /// A new goal, `distance` [m] away in a straight line with `path_left` [m] to drive;
  /// `driven` is the robot's odometer [m] (for the log only).
  void start(double now, double distance, double path_left, double driven);
  /// Registers the robot's state; true once it made no progress for longer than stuck_time.
  bool stuck(double now, double distance, double path_left, double driven);
  /// What a replan to the same goal was to the clock.
  enum class Replan {
    kSameWay,        ///< no restart: a similar way, or the detours are used up
    kForcedDetour,   ///< the clock restarted: the way is much longer than the blocked rest
    kWayBackOpened,  ///< on a forced detour, a way much shorter again: the restart is undone
  };
  /// A path to the same goal replaced one with `blocked_rest` [m] left: a way more than 1.2x
  /// the blocked rest + 1 m restarts the clock, and on it a shorter path left is progress
  /// (driving it leads away from the goal and from the best path left before); a way back
  /// under (rest - 1 m) / 1.2 during such a detour undoes the restart.
  Replan replanned(double now, double distance, double path_left, double blocked_rest, double driven);
  /// From now on a shorter path left is always progress (the second chance before trapped).
  void count_path_always() { options_.along_path = true; }
  /// Metres driven since the last progress.
  [[nodiscard]] double driven_since_progress(double driven) const { return driven - progress_.driven; }

 private:
  struct Progress {
    double best_distance = 0.0, best_path_left = 0.0, time = 0.0, driven = 0.0;
  };

  StuckClockOptions options_;
  Progress progress_;
  Progress before_detour_;  ///< the clock as a forced detour found it
  int detours_ = 0;         ///< forced detours that restarted the clock for this goal
  bool forced_ = false;     ///< on a forced detour: a shorter path left is progress
};

}  // namespace lookahead::exploration
