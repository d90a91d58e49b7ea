// SPDX-License-Identifier: MIT
// When does a robot driving to a goal give it up? When it has made no progress for
// stuck_time. Progress is getting kProgressStep closer to the goal in a straight line; a
// shorter path left counts too always (`along_path`) or only on a detour (`on_detours`:
// more than 10 m of path left, over twice the straight distance), where a ring corridor can
// lead away from the goal for minutes. The best path left is kept across replans, so a robot
// swapping between routes without shortening either is still stuck.
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
  /// From now on a shorter path left is always progress (the second chance before trapped).
  void count_path_always() { options_.along_path = true; }
  /// Metres driven since the last progress.
  [[nodiscard]] double driven_since_progress(double driven) const { return driven - progress_driven_; }

 private:
  StuckClockOptions options_;
  double best_distance_ = 0.0, best_path_left_ = 0.0, progress_time_ = 0.0, progress_driven_ = 0.0;
};

}  // namespace lookahead::exploration
