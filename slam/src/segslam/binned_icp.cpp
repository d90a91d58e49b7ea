// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/binned_icp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/SVD>

namespace lookahead::slam::segslam {
namespace {

std::int64_t bin_key(double x, double y, double bin) {
  const auto ix = static_cast<std::int64_t>(std::floor(x / bin));
  const auto iy = static_cast<std::int64_t>(std::floor(y / bin));
  return (ix << 32) ^ (iy & 0xffffffff);
}

// The target's points hashed by bin, for neighbour queries within max_distance.
class BinIndex {
 public:
  BinIndex(const Points2& points, double cell) : points_(points), cell_(cell) {
    for (std::size_t i = 0; i < points.size(); ++i) bins_[bin_key(points[i].x(), points[i].y(), cell_)].push_back(i);
  }
  /// Index of the nearest point within `max_d`, or -1.
  long nearest(const Eigen::Vector2d& q, double max_d) const {
    const int reach = static_cast<int>(std::ceil(max_d / cell_));
    long best = -1;
    double best_d2 = max_d * max_d;
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        const auto it = bins_.find(bin_key(q.x() + dx * cell_, q.y() + dy * cell_, cell_));
        if (it == bins_.end()) continue;
        for (std::size_t i : it->second) {
          const double d2 = (points_[i] - q).squaredNorm();
          if (d2 < best_d2) best_d2 = d2, best = static_cast<long>(i);
        }
      }
    }
    return best;
  }

 private:
  const Points2& points_;
  double cell_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> bins_;
};

Eigen::Vector2d apply(const Pose2& t, const Eigen::Vector2d& p) {
  const double c = std::cos(t.theta), s = std::sin(t.theta);
  return {t.x + c * p.x() - s * p.y(), t.y + s * p.x() + c * p.y()};
}

}  // namespace

Points2 bin_points(const Points2& points, double bin) {
  std::unordered_map<std::int64_t, std::pair<Eigen::Vector2d, int>> sums;
  Points2 out;
  for (const auto& p : points) {
    auto& [sum, n] = sums.try_emplace(bin_key(p.x(), p.y(), bin), Eigen::Vector2d::Zero(), 0).first->second;
    sum += p;
    ++n;
  }
  out.reserve(sums.size());
  for (const auto& [key, sn] : sums) out.push_back(sn.first / sn.second);
  // Hash order is not portable: sort so results do not depend on the library.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  return out;
}

IcpResult icp_binned(const Points2& source, const Points2& target, const Pose2& guess,
                     const IcpOptions& o) {
  IcpResult r;
  r.transform = guess;
  if (source.empty() || target.empty()) return r;
  const BinIndex index(target, std::max(o.bin, o.max_distance / 2));
  for (r.iterations = 0; r.iterations < o.iterations; ++r.iterations) {
    // Closed-form rigid alignment of the current pairs (Arun et al. 1987, 2D).
    Eigen::Vector2d ms = Eigen::Vector2d::Zero(), mt = Eigen::Vector2d::Zero();
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> pairs;
    for (const auto& p : source) {
      const Eigen::Vector2d q = apply(r.transform, p);
      const long j = index.nearest(q, o.max_distance);
      if (j >= 0) pairs.push_back({q, target[static_cast<std::size_t>(j)]});
    }
    if (pairs.size() < 3) break;
    for (const auto& [a, b] : pairs) ms += a, mt += b;
    ms /= static_cast<double>(pairs.size());
    mt /= static_cast<double>(pairs.size());
    double sxx = 0, sxy = 0;
    for (const auto& [a, b] : pairs) {
      const Eigen::Vector2d da = a - ms, db = b - mt;
      sxx += da.x() * db.x() + da.y() * db.y();
      sxy += da.x() * db.y() - da.y() * db.x();
    }
    const double dth = std::atan2(sxy, sxx);
    const double c = std::cos(dth), s = std::sin(dth);
    const Eigen::Vector2d shift = mt - Eigen::Vector2d(c * ms.x() - s * ms.y(), s * ms.x() + c * ms.y());
    const Pose2 step{shift.x(), shift.y(), dth};
    r.transform = step.compose(r.transform);
    if (shift.norm() < 1e-4 && std::abs(dth) < 1e-5) break;
  }
  double sum = 0;
  std::size_t inliers = 0;
  for (const auto& p : source) {
    const Eigen::Vector2d q = apply(r.transform, p);
    const long j = index.nearest(q, o.max_distance);
    if (j < 0) continue;
    sum += (target[static_cast<std::size_t>(j)] - q).norm();
    ++inliers;
  }
  r.inlier_ratio = static_cast<double>(inliers) / static_cast<double>(source.size());
  r.mean_error = inliers ? sum / static_cast<double>(inliers) : o.max_distance;
  return r;
}

}  // namespace lookahead::slam::segslam
