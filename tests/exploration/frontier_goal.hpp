// SPDX-License-Identifier: MIT
// A frontier cluster reduced to its goal, for tests of the strategies and of prediction
// targeting that look only at goals.
#pragma once

#include "lookahead/exploration/frontier_detector.hpp"

namespace lookahead::exploration {

inline FrontierCluster goal_at(double x, double y) {
  FrontierCluster f;
  f.has_goal = true;
  f.goal_x = x;
  f.goal_y = y;
  return f;
}

}  // namespace lookahead::exploration
