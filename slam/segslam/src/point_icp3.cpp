// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/point_icp3.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

namespace lookahead::slam::segslam {
namespace {

constexpr int kMinNormalNeighbours = 5;

Eigen::Vector3d apply(const Pose4& t, const Eigen::Vector3d& p) {
  const double c = std::cos(t.yaw), s = std::sin(t.yaw);
  return {t.x + c * p.x() - s * p.y(), t.y + s * p.x() + c * p.y(), t.z + p.z()};
}

}  // namespace

// Sorted by bin, then by index, so each bin's points add up in their input order (the order
// of the ordered map this replaced, whose node allocations were a share of every update:
// the window is binned at each one).
Points3 bin_points3(const Points3& points, double bin) {
  struct Keyed {
    long x, y, z;
    std::size_t index;
  };
  std::vector<Keyed> keyed(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d& p = points[i];
    keyed[i] = {std::lround(std::floor(p.x() / bin)), std::lround(std::floor(p.y() / bin)),
                std::lround(std::floor(p.z() / bin)), i};
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    return std::tie(a.x, a.y, a.z, a.index) < std::tie(b.x, b.y, b.z, b.index);
  });
  Points3 out;
  for (std::size_t first = 0; first < keyed.size();) {
    std::size_t last = first;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (; last < keyed.size() && keyed[last].x == keyed[first].x && keyed[last].y == keyed[first].y &&
           keyed[last].z == keyed[first].z;
         ++last) {
      sum += points[keyed[last].index];
      ++n;
    }
    out.push_back(sum / n);
    first = last;
  }
  return out;
}

IcpTarget3::IcpTarget3(Points3 points, double max_distance) : points_(std::move(points)), cell_(max_distance) {
  index_cells();
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

// A counting sort of the points by cell: stable, so each cell lists its points in index order.
void IcpTarget3::index_cells() {
  if (points_.empty()) return;
  long x1 = 0, y1 = 0, z1 = 0;
  x0_ = y0_ = z0_ = std::numeric_limits<long>::max();
  x1 = y1 = z1 = std::numeric_limits<long>::min();
  for (const auto& p : points_) {
    const long x = cell_of(p.x()), y = cell_of(p.y()), z = cell_of(p.z());
    x0_ = std::min(x0_, x), y0_ = std::min(y0_, y), z0_ = std::min(z0_, z);
    x1 = std::max(x1, x), y1 = std::max(y1, y), z1 = std::max(z1, z);
  }
  nx_ = x1 - x0_ + 1, ny_ = y1 - y0_ + 1, nz_ = z1 - z0_ + 1;
  if (nx_ > kMaxCells / ny_ / nz_) {
    throw std::invalid_argument("IcpTarget3: the cloud spans " + std::to_string(nx_) + " x " + std::to_string(ny_) +
                                " x " + std::to_string(nz_) + " cells, more than " + std::to_string(kMaxCells));
  }
  const auto cell = [&](const Eigen::Vector3d& p) {
    return static_cast<std::size_t>(((cell_of(p.z()) - z0_) * ny_ + (cell_of(p.y()) - y0_)) * nx_ +
                                    (cell_of(p.x()) - x0_));
  };
  first_.assign(static_cast<std::size_t>(nx_ * ny_ * nz_) + 1, 0);
  for (const auto& p : points_) ++first_[cell(p) + 1];
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  by_cell_.resize(points_.size());
  std::vector<std::uint32_t> next(first_.begin(), first_.end() - 1);
  for (std::size_t i = 0; i < points_.size(); ++i) by_cell_[next[cell(points_[i])]++] = static_cast<std::uint32_t>(i);
  by_cell_points_.resize(points_.size());
  for (std::size_t k = 0; k < by_cell_.size(); ++k) by_cell_points_[k] = points_[by_cell_[k]];
}

template <class F>
void IcpTarget3::for_each_near(const Eigen::Vector3d& q, F&& f) const {
  const long kx = cell_of(q.x()) - x0_, ky = cell_of(q.y()) - y0_, kz = cell_of(q.z()) - z0_;
  // x outermost, z innermost: the order of the hash grid this replaced, so equally near
  // points resolve as before and neighbour sums add up in the same order.
  for (long x = kx - 1; x <= kx + 1; ++x) {
    if (x < 0 || x >= nx_) continue;
    for (long y = ky - 1; y <= ky + 1; ++y) {
      if (y < 0 || y >= ny_) continue;
      for (long z = kz - 1; z <= kz + 1; ++z) {
        if (z < 0 || z >= nz_) continue;
        const auto c = static_cast<std::size_t>((z * ny_ + y) * nx_ + x);
        for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) f(static_cast<long>(by_cell_[k]));
      }
    }
  }
}

// The answer of a scan of the 27 cells in for_each_near's order keeping the last point with
// d2 <= the best so far: the least d2 within max_distance, of equal ones the last in that
// order (`rank`). Scanned from the query's own cell, which most often holds it, so the other
// cells whose box lies beyond the best so far are skipped (with a margin far above rounding).
long IcpTarget3::nearest(const Eigen::Vector3d& q) const {
  constexpr double kMargin = 1e-9;  // [m^2]
  const long kx = cell_of(q.x()), ky = cell_of(q.y()), kz = cell_of(q.z());
  // Squared distance from q to the faces of its cell below (index 0) and above (2) per axis.
  const auto faces = [&](double v, long k) {
    const double lo = v - static_cast<double>(k) * cell_, hi = static_cast<double>(k + 1) * cell_ - v;
    return std::array<double, 3>{lo > 0 ? lo * lo : 0.0, 0.0, hi > 0 ? hi * hi : 0.0};
  };
  const std::array<double, 3> fx = faces(q.x(), kx), fy = faces(q.y(), ky), fz = faces(q.z(), kz);
  long best = -1, best_rank = -1;
  double best_d2 = cell_ * cell_;
  const auto scan = [&](int dx, int dy, int dz) {
    const long x = kx + dx - x0_, y = ky + dy - y0_, z = kz + dz - z0_;
    if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return;
    if (fx[dx + 1] + fy[dy + 1] + fz[dz + 1] > best_d2 + kMargin) return;
    const auto c = static_cast<std::size_t>((z * ny_ + y) * nx_ + x);
    const long order = ((dx + 1) * 3 + (dy + 1)) * 3 + (dz + 1);
    for (std::uint32_t k = first_[c]; k < first_[c + 1]; ++k) {
      const double d2 = (by_cell_points_[k] - q).squaredNorm();
      const long rank = order * static_cast<long>(points_.size()) + by_cell_[k];
      if (d2 < best_d2 || (d2 == best_d2 && rank > best_rank)) best_d2 = d2, best = by_cell_[k], best_rank = rank;
    }
  };
  scan(0, 0, 0);
  // The same cells in the same order as testing all 26: a row or column whose nearer faces
  // already lie beyond the best is left at once (the faces' sum only grows).
  for (int dx = -1; dx <= 1; ++dx) {
    if (fx[dx + 1] > best_d2 + kMargin) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      if (fx[dx + 1] + fy[dy + 1] > best_d2 + kMargin) continue;
      for (int dz = -1; dz <= 1; ++dz) {
        if (dx != 0 || dy != 0 || dz != 0) scan(dx, dy, dz);
      }
    }
  }
  return best;
}

Icp3Result point_to_plane_fit(const Points3& source, const IcpTarget3& target, const Pose4& pose) {
  Icp3Result r;
  r.transform = pose;
  double error = 0;
  int inliers = 0;
  for (const auto& p : source) {
    const Eigen::Vector3d q = apply(pose, p);
    const long j = target.nearest(q);
    if (j < 0 || target.normal(j).isZero()) continue;
    error += std::abs(target.normal(j).dot(q - target.point(j)));
    ++inliers;
  }
  r.inlier_ratio = source.empty() ? 0.0 : static_cast<double>(inliers) / static_cast<double>(source.size());
  r.mean_error = inliers > 0 ? error / inliers : 0.0;
  return r;
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
