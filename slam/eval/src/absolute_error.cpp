// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/absolute_error.hpp"

#include <algorithm>
#include <cmath>

namespace lookahead::slam {
namespace {

struct Pair {
  double rx, ry, ex, ey;
};

std::vector<Pair> match_by_stamp(const std::vector<StampedPose>& reference, std::vector<StampedPose> estimate,
                                 double tolerance) {
  std::stable_sort(estimate.begin(), estimate.end(),
                   [](const StampedPose& a, const StampedPose& b) { return a.t < b.t; });
  std::vector<Pair> pairs;
  for (const StampedPose& r : reference) {
    auto it =
        std::lower_bound(estimate.begin(), estimate.end(), r.t, [](const StampedPose& p, double v) { return p.t < v; });
    const StampedPose* best = nullptr;
    if (it != estimate.end()) best = &*it;
    if (it != estimate.begin() && (!best || r.t - (it - 1)->t < best->t - r.t)) best = &*(it - 1);
    if (best && std::abs(best->t - r.t) <= tolerance) {
      pairs.push_back({r.pose.x, r.pose.y, best->pose.x, best->pose.y});
    }
  }
  return pairs;
}

}  // namespace

AbsoluteError absolute_trajectory_error(const std::vector<StampedPose>& reference,
                                        const std::vector<StampedPose>& estimate, double tolerance) {
  AbsoluteError out;
  const std::vector<Pair> pairs = match_by_stamp(reference, estimate, tolerance);
  out.matched = pairs.size();
  if (pairs.empty()) return out;
  const double n = static_cast<double>(pairs.size());
  double rcx = 0, rcy = 0, ecx = 0, ecy = 0;
  for (const Pair& p : pairs) {
    rcx += p.rx / n;
    rcy += p.ry / n;
    ecx += p.ex / n;
    ecy += p.ey / n;
  }
  // The rotation maximising sum r_i . R e_i (centred): atan2 of the summed cross and dot.
  double dot = 0, cross = 0;
  for (const Pair& p : pairs) {
    const double ex = p.ex - ecx, ey = p.ey - ecy, rx = p.rx - rcx, ry = p.ry - rcy;
    dot += ex * rx + ey * ry;
    cross += ex * ry - ey * rx;
  }
  const double th = std::atan2(cross, dot);
  const double c = std::cos(th), s = std::sin(th);
  out.alignment = {rcx - (c * ecx - s * ecy), rcy - (s * ecx + c * ecy), th};
  double sq = 0;
  for (const Pair& p : pairs) {
    const double ax = out.alignment.x + c * p.ex - s * p.ey;
    const double ay = out.alignment.y + s * p.ex + c * p.ey;
    const double e = std::hypot(ax - p.rx, ay - p.ry);
    sq += e * e;
    out.mean += e / n;
    out.max = std::max(out.max, e);
  }
  out.rmse = std::sqrt(sq / n);
  return out;
}

}  // namespace lookahead::slam
