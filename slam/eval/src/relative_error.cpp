// SPDX-License-Identifier: MIT
#include "lookahead/slam/eval/relative_error.hpp"

#include <algorithm>
#include <cmath>

#include "lookahead/slam/io/carmen_fields.hpp"
#include "lookahead/slam/io/line_reader.hpp"

namespace lookahead::slam {
namespace {

const StampedPose* nearest(const std::vector<StampedPose>& sorted, double t, double tolerance) {
  auto it = std::lower_bound(sorted.begin(), sorted.end(), t, [](const StampedPose& p, double v) { return p.t < v; });
  const StampedPose* best = nullptr;
  if (it != sorted.end()) best = &*it;
  if (it != sorted.begin() && (!best || t - (it - 1)->t < best->t - t)) best = &*(it - 1);
  return (best && std::abs(best->t - t) <= tolerance) ? best : nullptr;
}

void mean_std(const std::vector<double>& v, double& mean, double& sd) {
  mean = sd = 0.0;
  if (v.empty()) return;
  for (const double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  for (const double x : v) sd += (x - mean) * (x - mean);
  sd = std::sqrt(sd / static_cast<double>(v.size()));
}

}  // namespace

std::vector<Relation> read_relations(const std::string& path) {
  std::vector<Relation> out;
  LineReader reader(path);
  std::string line;
  while (reader.next(line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const carmen::Fields f(path, reader.line_number(), line);
    if (f.size() != 8) f.fail("fields", std::to_string(f.size()), "expected 't1 t2 x y z roll pitch yaw'");
    out.push_back({f.number(0, "t1"),
                   f.number(1, "t2"),
                   {f.number(2, "x"), f.number(3, "y"), normalize_angle(f.number(7, "yaw"))}});
  }
  return out;
}

RelativeError relative_error(const std::vector<Relation>& relations, const std::vector<StampedPose>& trajectory,
                             double tolerance) {
  std::vector<StampedPose> sorted = trajectory;
  std::stable_sort(sorted.begin(), sorted.end(), [](const StampedPose& a, const StampedPose& b) { return a.t < b.t; });
  std::vector<double> trans, rot;
  RelativeError e;
  for (const Relation& r : relations) {
    const StampedPose* a = nearest(sorted, r.t1, tolerance);
    const StampedPose* b = nearest(sorted, r.t2, tolerance);
    if (!a || !b) {
      ++e.skipped;
      continue;
    }
    // Error of the estimated relative motion against the reference one.
    const Pose2 err = r.delta.between(a->pose.between(b->pose));
    trans.push_back(err.norm());
    rot.push_back(std::abs(err.theta) * 180.0 / M_PI);
  }
  e.used = trans.size();
  mean_std(trans, e.trans_mean, e.trans_std);
  mean_std(rot, e.rot_mean, e.rot_std);
  return e;
}

std::vector<Relation> relations_from_reference(const std::vector<StampedPose>& reference, std::size_t stride) {
  std::vector<Relation> out;
  stride = std::max<std::size_t>(1, stride);
  for (std::size_t i = 0; i + stride < reference.size(); ++i) {
    const StampedPose& a = reference[i];
    const StampedPose& b = reference[i + stride];
    out.push_back({a.t, b.t, a.pose.between(b.pose)});
  }
  return out;
}

}  // namespace lookahead::slam
