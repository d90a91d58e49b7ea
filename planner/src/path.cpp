// SPDX-License-Identifier: MIT
#include "lookahead/planner/path.hpp"

#include <cmath>

namespace lookahead::planner {

double distance(Point2 a, Point2 b) { return std::hypot(b.x - a.x, b.y - a.y); }

double path_length(const Path& path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += distance(path[i - 1], path[i]);
  return length;
}

}  // namespace lookahead::planner
