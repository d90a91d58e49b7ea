// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/map_joining.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "lookahead/slam/hybrid/gaussian_map.hpp"

namespace lookahead::slam::hybrid {
namespace {

// d R(theta)^T / d theta
Eigen::Matrix2d rotation_transpose_derivative(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d d;
  d << -s, c, -c, -s;
  return d;
}

Eigen::Matrix2d rotation_transpose(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, s, -s, c;
  return r;
}

}  // namespace

MapJoining::MapJoining(const Pose2& start) : poses_{start} {}

Eigen::Index MapJoining::feature_column(int feature) const {
  return 3 * static_cast<Eigen::Index>(poses_.size() - 1) + 2 * static_cast<Eigen::Index>(feature);
}

Eigen::Index MapJoining::columns() const { return feature_column(static_cast<int>(features_.size())); }

void MapJoining::add(const GaussianMap& local, const std::vector<int>& feature_of, const Pose2& pose_guess,
                     const std::vector<Eigen::Vector2d>& new_feature_guess) {
  if (feature_of.size() != local.features()) throw std::invalid_argument("MapJoining::add: one target per feature");
  Factor f;
  f.from = static_cast<int>(poses_.size()) - 1;
  f.mean = local.mean;
  const Eigen::Index n = local.mean.size();
  // The local map's covariance is full rank (landmark EKFs, particle spread); the floor
  // only guards the inverse against round-off.
  const Eigen::MatrixXd p = local.covariance + 1e-12 * Eigen::MatrixXd::Identity(n, n);
  f.information = p.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
  f.information = 0.5 * (f.information + f.information.transpose());
  std::size_t next_new = 0;
  for (int target : feature_of) {
    if (target >= 0) {
      f.features.push_back(target);
      continue;
    }
    if (next_new >= new_feature_guess.size()) throw std::invalid_argument("MapJoining::add: a guess per new feature");
    f.features.push_back(static_cast<int>(features_.size()));
    features_.push_back(new_feature_guess[next_new++]);
  }
  poses_.push_back(pose_guess);
  factors_.push_back(std::move(f));
}

// The local map predicted from the global variables, minus the local map: r(x) and dr/dx
// over the columns `cols` (the origin's, unless it is the fixed start; the end pose's;
// each feature's).
void MapJoining::residual_and_jacobian(const Factor& f, Eigen::VectorXd& r, Eigen::MatrixXd& j,
                                       std::vector<Eigen::Index>& cols) const {
  const Pose2& o = poses_[static_cast<std::size_t>(f.from)];
  const Pose2& v = poses_[static_cast<std::size_t>(f.from) + 1];
  const Eigen::Vector2d t(o.x, o.y);
  const Eigen::Matrix2d rt = rotation_transpose(o.theta), drt = rotation_transpose_derivative(o.theta);
  const bool free_origin = f.from > 0;
  const Eigen::Index rows = f.mean.size(), origin_cols = free_origin ? 3 : 0;
  r.resize(rows);
  j = Eigen::MatrixXd::Zero(rows, origin_cols + 3 + 2 * static_cast<Eigen::Index>(f.features.size()));
  cols.clear();
  if (free_origin) {
    for (int i = 0; i < 3; ++i) cols.push_back(pose_column(f.from) + i);
  }
  for (int i = 0; i < 3; ++i) cols.push_back(pose_column(f.from + 1) + i);
  // A point p seen from the origin: R^T (p - t); d/dt = -R^T, d/dtheta = dR^T (p - t), d/dp = R^T.
  const auto point = [&](Eigen::Index row, const Eigen::Vector2d& p, Eigen::Index col) {
    r.segment<2>(row) = rt * (p - t) - f.mean.segment<2>(row);
    if (free_origin) {
      j.block<2, 2>(row, 0) = -rt;
      j.block<2, 1>(row, 2) = drt * (p - t);
    }
    j.block<2, 2>(row, col) = rt;
  };
  point(0, Eigen::Vector2d(v.x, v.y), origin_cols);
  r(2) = normalize_angle(v.theta - o.theta - f.mean(2));
  if (free_origin) j(2, 2) = -1.0;
  j(2, origin_cols + 2) = 1.0;
  for (std::size_t k = 0; k < f.features.size(); ++k) {
    const Eigen::Index row = 3 + 2 * static_cast<Eigen::Index>(k),
                       col = origin_cols + 3 + 2 * static_cast<Eigen::Index>(k);
    point(row, features_[static_cast<std::size_t>(f.features[k])], col);
    cols.push_back(feature_column(f.features[k]));
    cols.push_back(feature_column(f.features[k]) + 1);
  }
}

// Sum over the local maps of J^T Omega J, and of J^T Omega r into `gradient` when given.
Eigen::MatrixXd MapJoining::information(Eigen::VectorXd* gradient) const {
  const Eigen::Index n = columns();
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  if (gradient != nullptr) *gradient = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd r;
  Eigen::MatrixXd j;
  std::vector<Eigen::Index> cols;
  for (const Factor& f : factors_) {
    residual_and_jacobian(f, r, j, cols);
    const Eigen::MatrixXd jt_omega = j.transpose() * f.information;
    const Eigen::MatrixXd local_a = jt_omega * j;
    const Eigen::VectorXd local_g = jt_omega * r;
    for (std::size_t p = 0; p < cols.size(); ++p) {
      if (gradient != nullptr) (*gradient)(cols[p]) += local_g(static_cast<Eigen::Index>(p));
      for (std::size_t q = 0; q < cols.size(); ++q) {
        a(cols[p], cols[q]) += local_a(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(q));
      }
    }
  }
  return a;
}

int MapJoining::solve(int iterations) {
  constexpr double kConverged = 1e-7;  // largest step [m or rad]
  for (int it = 0; it < iterations; ++it) {
    Eigen::VectorXd g;
    const Eigen::MatrixXd a = information(&g);
    const Eigen::VectorXd step = a.ldlt().solve(-g);
    if (!step.allFinite()) throw std::runtime_error("MapJoining::solve: singular information");
    for (std::size_t k = 1; k < poses_.size(); ++k) {
      const Eigen::Vector3d d = step.segment<3>(pose_column(static_cast<int>(k)));
      poses_[k] = {poses_[k].x + d.x(), poses_[k].y + d.y(), normalize_angle(poses_[k].theta + d.z())};
    }
    for (std::size_t m = 0; m < features_.size(); ++m)
      features_[m] += step.segment<2>(feature_column(static_cast<int>(m)));
    if (step.cwiseAbs().maxCoeff() < kConverged) return it + 1;
  }
  return iterations;
}

void MapJoining::marginal(Eigen::VectorXd& mean, Eigen::MatrixXd& covariance) const {
  const Eigen::Index n = columns(), m = 3 + 2 * static_cast<Eigen::Index>(features_.size());
  const Pose2& v = poses_.back();
  mean.resize(m);
  mean.head<3>() << v.x, v.y, v.theta;
  for (std::size_t k = 0; k < features_.size(); ++k)
    mean.segment<2>(3 + 2 * static_cast<Eigen::Index>(k)) = features_[k];
  if (poses_.size() == 1) {  // nothing fused yet: the start, exactly
    covariance = Eigen::MatrixXd::Zero(m, m);
    return;
  }
  // Columns of [newest pose, features] in the joint covariance A^-1.
  std::vector<Eigen::Index> keep;
  for (int i = 0; i < 3; ++i) keep.push_back(pose_column(static_cast<int>(poses_.size()) - 1) + i);
  for (Eigen::Index c = feature_column(0); c < n; ++c) keep.push_back(c);
  Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(n, m);
  for (Eigen::Index c = 0; c < m; ++c) unit(keep[static_cast<std::size_t>(c)], c) = 1.0;
  const Eigen::MatrixXd columns_of_inverse = information(nullptr).ldlt().solve(unit);
  covariance.resize(m, m);
  for (Eigen::Index r = 0; r < m; ++r) covariance.row(r) = columns_of_inverse.row(keep[static_cast<std::size_t>(r)]);
  covariance = 0.5 * (covariance + covariance.transpose());
}

}  // namespace lookahead::slam::hybrid
