// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/binned_icp.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

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
  BinIndex(Points2 points, double cell) : points_(std::move(points)), cell_(cell) {
    for (std::size_t i = 0; i < points_.size(); ++i) bins_[bin_key(points_[i].x(), points_[i].y(), cell_)].push_back(i);
  }
  /// Indices of the points within `radius` of q.
  std::vector<std::size_t> within(const Eigen::Vector2d& q, double radius) const {
    const int reach = static_cast<int>(std::ceil(radius / cell_));
    std::vector<std::size_t> out;
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        const auto it = bins_.find(bin_key(q.x() + dx * cell_, q.y() + dy * cell_, cell_));
        if (it == bins_.end()) continue;
        for (std::size_t i : it->second) {
          if ((points_[i] - q).norm() <= radius) out.push_back(i);
        }
      }
    }
    return out;
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
  [[nodiscard]] const Points2& points() const { return points_; }

 private:
  Points2 points_;
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

namespace {

// Unit normal of the target around each point, from the points within `radius` (the
// direction of least spread); zero where there are too few to tell.
std::vector<Eigen::Vector2d> normals_of(const Points2& target, const BinIndex& index, double radius) {
  std::vector<Eigen::Vector2d> normals(target.size(), Eigen::Vector2d::Zero());
  for (std::size_t i = 0; i < target.size(); ++i) {
    const std::vector<std::size_t> near = index.within(target[i], radius);
    if (near.size() < 3) continue;
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (std::size_t j : near) mean += target[j];
    mean /= static_cast<double>(near.size());
    Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
    for (std::size_t j : near) cov += (target[j] - mean) * (target[j] - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
    normals[i] = eig.eigenvectors().col(0);  // eigenvalues ascending
  }
  return normals;
}

}  // namespace

struct IcpTarget::Data {
  BinIndex index;
  std::vector<Eigen::Vector2d> normals;
};

IcpTarget::IcpTarget(Points2 points, const IcpOptions& o)
    : data_(std::make_unique<Data>(Data{BinIndex(std::move(points), std::max(o.bin, o.max_distance / 2)), {}})) {
  data_->normals = normals_of(data_->index.points(), data_->index, 2.5 * o.bin);
}
IcpTarget::~IcpTarget() = default;
IcpTarget::IcpTarget(IcpTarget&&) noexcept = default;
IcpTarget& IcpTarget::operator=(IcpTarget&&) noexcept = default;
std::size_t IcpTarget::size() const { return data_->index.points().size(); }

IcpResult icp_binned(const Points2& source, const Points2& target, const Pose2& guess, const IcpOptions& o) {
  return icp_binned(source, IcpTarget(target, o), guess, o);
}

IcpResult icp_binned(const Points2& source, const IcpTarget& prepared, const Pose2& guess,
                     const IcpOptions& o) {
  IcpResult r;
  r.transform = guess;
  const BinIndex& index = prepared.data_->index;
  const Points2& target = index.points();
  const std::vector<Eigen::Vector2d>& normals = prepared.data_->normals;
  if (source.empty() || target.empty()) return r;
  // Deviation: point-to-line, not point-to-point. With one point per bin, point-to-point ICP
  // stalls up to half a bin off along walls (a neighbour bin is never nearer); the
  // distance to the wall through the nearest bin has no such dead zone.
  for (r.iterations = 0; r.iterations < o.iterations; ++r.iterations) {
    // Gauss-Newton on sum (n . (T p - q))^2 for a small step (dx, dy, dtheta) after T.
    Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    int pairs = 0;
    for (const auto& p : source) {
      const Eigen::Vector2d a = apply(r.transform, p);
      const long j = index.nearest(a, o.max_distance);
      if (j < 0) continue;
      const auto k = static_cast<std::size_t>(j);
      const Eigen::Vector2d d = a - target[k];
      auto add = [&](const Eigen::Vector2d& n) {
        const Eigen::Vector3d jac(n.x(), n.y(), a.x() * n.y() - a.y() * n.x());
        h += jac * jac.transpose();
        g += jac * n.dot(d);
      };
      if (normals[k].squaredNorm() > 0) {
        add(normals[k]);
      } else {
        add({1, 0});
        add({0, 1});
      }
      ++pairs;
    }
    if (pairs < 3) break;
    const Eigen::Vector3d delta = h.ldlt().solve(-g);
    if (!delta.allFinite()) break;
    r.transform = Pose2{delta.x(), delta.y(), delta.z()}.compose(r.transform);
    if (delta.head<2>().norm() < 1e-5 && std::abs(delta.z()) < 1e-6) break;
  }
  double sum = 0;
  std::size_t inliers = 0;
  for (const auto& p : source) {
    const Eigen::Vector2d q = apply(r.transform, p);
    const long j = index.nearest(q, o.max_distance);
    if (j < 0) continue;
    const auto k = static_cast<std::size_t>(j);
    const Eigen::Vector2d d = q - target[k];
    sum += normals[k].squaredNorm() > 0 ? std::abs(normals[k].dot(d)) : d.norm();
    ++inliers;
  }
  r.inlier_ratio = static_cast<double>(inliers) / static_cast<double>(source.size());
  r.mean_error = inliers ? sum / static_cast<double>(inliers) : o.max_distance;
  return r;
}

}  // namespace lookahead::slam::segslam
