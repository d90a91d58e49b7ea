// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/binned_icp.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace lookahead::slam::segslam {
namespace {

std::int64_t bin_key(double x, double y, double bin) {
  const auto ix = static_cast<std::int64_t>(std::floor(x / bin));
  const auto iy = static_cast<std::int64_t>(std::floor(y / bin));
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) ^
                                   (static_cast<std::uint64_t>(iy) & 0xffffffff));
}

// The target's points sorted into a dense grid of square cells (counting sort, so each
// cell lists its points in index order), for neighbour queries within max_distance: a cell
// is one array read, where a hash of bins cost most of ICP's time.
class BinIndex {
 public:
  BinIndex(Points2 points, double cell) : points_(std::move(points)), cell_(cell) {
    if (points_.empty()) return;
    double x0 = points_[0].x(), y0 = points_[0].y(), x1 = x0, y1 = y0;
    for (const auto& p : points_)
      x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
    ix0_ = static_cast<long>(std::floor(x0 / cell_)), iy0_ = static_cast<long>(std::floor(y0 / cell_));
    w_ = static_cast<long>(std::floor(x1 / cell_)) - ix0_ + 1,
    h_ = static_cast<long>(std::floor(y1 / cell_)) - iy0_ + 1;
    start_.assign(static_cast<std::size_t>(w_ * h_ + 1), 0);
    std::vector<std::size_t> cell_of(points_.size());
    for (std::size_t i = 0; i < points_.size(); ++i) {
      cell_of[i] = static_cast<std::size_t>(slot(static_cast<long>(std::floor(points_[i].x() / cell_)),
                                                 static_cast<long>(std::floor(points_[i].y() / cell_))));
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(points_.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points_.size(); ++i) order_[fill[cell_of[i]]++] = i;
  }
  /// Indices of the points within `radius` of q, into `out` (reused: no allocation per query).
  void within(const Eigen::Vector2d& q, double radius, std::vector<std::size_t>& out) const {
    out.clear();
    for_each_near(q, radius, [&](std::size_t i) {
      if ((points_[i] - q).norm() <= radius) out.push_back(i);
    });
  }
  /// Index of the nearest point within `max_d`, or -1.
  long nearest(const Eigen::Vector2d& q, double max_d) const {
    long best = -1;
    double best_d2 = max_d * max_d;
    for_each_near(q, max_d, [&](std::size_t i) {
      const double d2 = (points_[i] - q).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = static_cast<long>(i);
    });
    return best;
  }
  [[nodiscard]] const Points2& points() const { return points_; }

 private:
  long slot(long ix, long iy) const { return (iy - iy0_) * w_ + (ix - ix0_); }
  // Every point of the cells within `radius` of q's cell (a superset of the points within it).
  template <typename F>
  void for_each_near(const Eigen::Vector2d& q, double radius, F&& f) const {
    if (points_.empty()) return;
    const long reach = static_cast<long>(std::ceil(radius / cell_));
    const long qx = static_cast<long>(std::floor(q.x() / cell_)), qy = static_cast<long>(std::floor(q.y() / cell_));
    for (long ix = std::max(qx - reach, ix0_); ix <= std::min(qx + reach, ix0_ + w_ - 1); ++ix) {
      for (long iy = std::max(qy - reach, iy0_); iy <= std::min(qy + reach, iy0_ + h_ - 1); ++iy) {
        const auto c = static_cast<std::size_t>(slot(ix, iy));
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) f(order_[k]);
      }
    }
  }

  Points2 points_;
  double cell_;
  long ix0_ = 0, iy0_ = 0, w_ = 0, h_ = 0;  // first cell and extent of the grid [cells]
  std::vector<std::size_t> start_;          // cell c's points are order_[start_[c] .. start_[c + 1])
  std::vector<std::size_t> order_;
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
  std::sort(out.begin(), out.end(),
            [](const auto& a, const auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  return out;
}

namespace {

// Unit normal of the target around each point, from the points within `radius` (the
// direction of least spread); zero where there are too few to tell.
std::vector<Eigen::Vector2d> normals_of(const Points2& target, const BinIndex& index, double radius) {
  std::vector<Eigen::Vector2d> normals(target.size(), Eigen::Vector2d::Zero());
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < target.size(); ++i) {
    index.within(target[i], radius, near);
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

IcpResult icp_binned(const Points2& source, const IcpTarget& prepared, const Pose2& guess, const IcpOptions& o) {
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
