// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/point_icp3.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <map>
#include <tuple>

namespace lookahead::slam::segslam {
namespace {

constexpr int kMinNormalNeighbours = 5;

std::int64_t pack(long x, long y, long z) {
  // 21 bits per axis: +-1e6 bins, far beyond any map here.
  const auto u = [](long v) { return static_cast<std::int64_t>(v + (1L << 20)) & ((1LL << 21) - 1); };
  return (u(x) << 42) | (u(y) << 21) | u(z);
}

Eigen::Vector3d apply(const Pose4& t, const Eigen::Vector3d& p) {
  const double c = std::cos(t.yaw), s = std::sin(t.yaw);
  return {t.x + c * p.x() - s * p.y(), t.y + s * p.x() + c * p.y(), t.z + p.z()};
}

}  // namespace

Points3 bin_points3(const Points3& points, double bin) {
  std::map<std::tuple<long, long, long>, std::pair<Eigen::Vector3d, int>> bins;
  for (const auto& p : points) {
    auto& [sum, n] = bins[{std::lround(std::floor(p.x() / bin)), std::lround(std::floor(p.y() / bin)),
                           std::lround(std::floor(p.z() / bin))}];
    if (n == 0) sum.setZero();
    sum += p;
    ++n;
  }
  Points3 out;
  out.reserve(bins.size());
  for (const auto& [key, sn] : bins) out.push_back(sn.first / sn.second);
  return out;
}

IcpTarget3::IcpTarget3(Points3 points, double max_distance) : points_(std::move(points)), cell_(max_distance) {
  for (std::size_t i = 0; i < points_.size(); ++i) cells_[cell_key(points_[i])].push_back(static_cast<long>(i));
  normals_.assign(points_.size(), Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < points_.size(); ++i) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
    int n = 0;
    for_each_near(points_[i], [&](long j) {
      const Eigen::Vector3d& q = points_[static_cast<std::size_t>(j)];
      if ((q - points_[i]).norm() > cell_) return;
      mean += q, second += q * q.transpose(), ++n;
    });
    if (n < kMinNormalNeighbours) continue;
    mean /= n;
    const Eigen::Matrix3d cov = second / n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    normals_[i] = eig.eigenvectors().col(0);  // the smallest eigenvalue's direction
  }
}

std::int64_t IcpTarget3::cell_key(const Eigen::Vector3d& p, int dx, int dy, int dz) const {
  return pack(std::lround(std::floor(p.x() / cell_)) + dx, std::lround(std::floor(p.y() / cell_)) + dy,
              std::lround(std::floor(p.z() / cell_)) + dz);
}

template <class F>
void IcpTarget3::for_each_near(const Eigen::Vector3d& q, F&& f) const {
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        const auto it = cells_.find(cell_key(q, dx, dy, dz));
        if (it == cells_.end()) continue;
        for (long j : it->second) f(j);
      }
    }
  }
}

long IcpTarget3::nearest(const Eigen::Vector3d& q) const {
  long best = -1;
  double best_d2 = cell_ * cell_;
  for_each_near(q, [&](long j) {
    const double d2 = (points_[static_cast<std::size_t>(j)] - q).squaredNorm();
    if (d2 <= best_d2) best_d2 = d2, best = j;
  });
  return best;
}

Icp3Result icp_point_to_plane(const Points3& source, const IcpTarget3& target, const Pose4& initial,
                              const Icp3Options& o) {
  Icp3Result r;
  r.transform = initial;
  for (int it = 0; it < o.iterations; ++it) {
    // Normal equations of the residual n . (R(yaw) p + t - q) in (tx, ty, tz, yaw).
    Eigen::Matrix4d h = Eigen::Matrix4d::Zero();
    Eigen::Vector4d g = Eigen::Vector4d::Zero();
    double error = 0;
    int inliers = 0;
    for (const auto& p : source) {
      const Eigen::Vector3d q = apply(r.transform, p);
      const long j = target.nearest(q);
      if (j < 0 || target.normal(j).isZero()) continue;
      const Eigen::Vector3d& n = target.normal(j);
      const double res = n.dot(q - target.point(j));
      const Eigen::Vector3d dq_dyaw(-(q.y() - r.transform.y), q.x() - r.transform.x, 0.0);
      const Eigen::Vector4d jac(n.x(), n.y(), n.z(), n.dot(dq_dyaw));
      h += jac * jac.transpose();
      g += jac * res;
      error += std::abs(res);
      ++inliers;
    }
    r.inlier_ratio = source.empty() ? 0.0 : static_cast<double>(inliers) / static_cast<double>(source.size());
    r.mean_error = inliers > 0 ? error / inliers : 0.0;
    if (inliers < 6) break;
    h.diagonal().array() += 1e-6 * h.trace();  // keeps a degenerate scene (one plane) solvable
    const Eigen::Vector4d step = h.ldlt().solve(-g);
    r.transform = {r.transform.x + step(0), r.transform.y + step(1), r.transform.z + step(2),
                   normalize_angle(r.transform.yaw + step(3))};
    if (step.head<3>().norm() < 1e-4 && std::abs(step(3)) < 1e-5) break;
  }
  return r;
}

}  // namespace lookahead::slam::segslam
