// SPDX-License-Identifier: MIT
// Goals that failed (unreachable, planner time-out, robot stuck) are avoided for a while:
// new map data may open a way later, so entries expire instead of lasting forever.
#pragma once

#include <vector>

namespace lookahead::exploration {

struct BlacklistOptions {
  double radius = 0.5;     ///< goals this close to a failed one are skipped too [m]
  double lifetime = 60.0;  ///< seconds of mission time an entry lasts
};

class GoalBlacklist {
 public:
  explicit GoalBlacklist(const BlacklistOptions& options = {}) : options_(options) {}

  void add(double x, double y, double now) { entries_.push_back({x, y, now + options_.lifetime}); }
  [[nodiscard]] bool contains(double x, double y, double now) const;
  /// Drops expired entries; returns how many remain.
  std::size_t expire(double now);
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double x, y, expires;
  };
  BlacklistOptions options_;
  std::vector<Entry> entries_;
};

}  // namespace lookahead::exploration
