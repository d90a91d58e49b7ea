// SPDX-License-Identifier: MIT
#include "lookahead/exploration/breadcrumbs.hpp"

#include <cmath>
#include <stdexcept>

namespace lookahead::exploration {

Breadcrumbs::Breadcrumbs(double spacing) : spacing_(spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("Breadcrumbs: spacing must be > 0");
}

void Breadcrumbs::drop(planner::Point2 p) {
  if (!crumbs_.empty() && std::hypot(p.x - crumbs_.back().x, p.y - crumbs_.back().y) < spacing_) return;
  crumbs_.push_back(p);
}

planner::Path Breadcrumbs::backtrack(planner::Point2 from, const std::function<bool(planner::Point2)>& outside) {
  std::size_t k = crumbs_.size();
  while (k > 0 && !outside(crumbs_[k - 1])) --k;
  if (k == 0) return {};
  planner::Path path{from};
  for (std::size_t i = crumbs_.size(); i-- > k - 1;) path.push_back(crumbs_[i]);
  crumbs_.resize(k);  // the exit crumb stays: the trail goes on from there
  return path;
}

}  // namespace lookahead::exploration
