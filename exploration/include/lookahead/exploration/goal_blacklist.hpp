// SPDX-License-Identifier: MIT
// Goals that failed (unreachable, planner time-out, robot stuck) are avoided for a while:
// new map data may open a way later, so entries expire instead of lasting forever. A spot
// that keeps failing stays blacklisted for good after max_strikes entries: retrying it every
// lifetime would keep a mission that has nothing else left waiting until its time limit.
#pragma once

#include <vector>

namespace lookahead::exploration {

struct BlacklistOptions {
  double radius = 0.5;     ///< goals this close to a failed one are skipped too [m]
  double lifetime = 60.0;  ///< seconds of mission time an entry lasts
  int max_strikes = 3;     ///< the max_strikes-th entry at one spot lasts for good; >= 1
};

class GoalBlacklist {
 public:
  explicit GoalBlacklist(const BlacklistOptions& options = {}) : options_(options) {}

  /// Blacklists (x, y) for `lifetime`, or for good at its max_strikes-th time (a spot is
  /// the same when within `radius`). Returns true when the entry is for good.
  bool add(double x, double y, double now);
  [[nodiscard]] bool contains(double x, double y, double now) const;
  /// (x, y) is blacklisted for good: waiting for its entry to expire is pointless.
  [[nodiscard]] bool permanent(double x, double y) const;
  /// Gives every spot blacklisted for good its strikes back (its entries are dropped);
  /// returns how many spots were forgiven.
  std::size_t forgive_permanent();
  /// Drops expired entries; returns how many remain.
  std::size_t expire(double now);
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double x, y, expires;
  };
  struct Spot {
    double x, y;
    int strikes;
  };
  BlacklistOptions options_;
  std::vector<Entry> entries_;
  std::vector<Spot> spots_;  ///< every spot ever added, with its count (expiry keeps these)
};

}  // namespace lookahead::exploration
