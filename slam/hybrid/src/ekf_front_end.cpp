// SPDX-License-Identifier: MIT
#include "ekf_front_end.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "jcbb.hpp"

namespace lookahead::slam::hybrid {
namespace {

Eigen::Index slot(std::size_t k) { return 3 + 2 * static_cast<Eigen::Index>(k); }

}  // namespace

EkfFrontEnd::EkfFrontEnd(const HybridOptions& options) : options_(options), existence_(options.existence) { restart(); }

void EkfFrontEnd::restart() {
  x_ = Eigen::VectorXd::Zero(3);
  p_ = Eigen::MatrixXd::Zero(3, 3);
  ids_.clear();
  existence_of_.clear();
}

void EkfFrontEnd::predict(const MotionStep& step) {
  const Pose2 v = to_pose(x_.head<3>());
  const MotionJacobians j = motion_jacobians(v, step.delta);
  x_.head<3>() = to_vector(v.compose(step.delta));
  p_.topRows<3>() = j.d_pose * p_.topRows<3>();
  p_.leftCols<3>() = p_.leftCols<3>() * j.d_pose.transpose();
  p_.topLeftCorner<3, 3>() += control_covariance(v, step);
}

void EkfFrontEnd::observe(const std::vector<RangeBearing>& z) {
  const std::vector<int> match = associate(z);
  update(z, match);
  update_existence(match);
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (match[i] < 0) add_feature(z[i]);
  }
}

std::vector<int> EkfFrontEnd::associate(const std::vector<RangeBearing>& z) const {
  const Pose2 v = to_pose(x_.head<3>());
  const Eigen::Index n = x_.size();
  const double gate = chi2_quantile(2, options_.fusion.jcbb_confidence);
  std::vector<PairingCandidate> candidates;
  for (std::size_t i = 0; i < z.size(); ++i) {
    for (std::size_t k = 0; k < ids_.size(); ++k) {
      const PredictedObservation h = predict_observation(v, x_.segment<2>(slot(k)));
      PairingCandidate c{static_cast<int>(i), static_cast<int>(k), innovation(z[i], h.z), Eigen::MatrixXd::Zero(2, n),
                         z[i].noise};
      c.jacobian.leftCols<3>() = h.d_pose;
      c.jacobian.middleCols<2>(slot(k)) = h.d_point;
      const Eigen::Matrix2d s = c.jacobian * p_ * c.jacobian.transpose() + c.noise;
      if (c.nu.dot(s.ldlt().solve(c.nu)) <= gate) candidates.push_back(std::move(c));
    }
  }
  return jcbb(static_cast<int>(z.size()), candidates, p_, options_.fusion.jcbb_confidence,
              options_.fusion.jcbb_max_nodes)
      .target_of;
}

// One batch EKF update with every associated observation.
void EkfFrontEnd::update(const std::vector<RangeBearing>& z, const std::vector<int>& match) {
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (match[i] >= 0) used.push_back(i);
  }
  if (used.empty()) return;
  const Pose2 v = to_pose(x_.head<3>());
  const Eigen::Index m = 2 * static_cast<Eigen::Index>(used.size()), n = x_.size();
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m, n), r = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd nu(m);
  for (std::size_t u = 0; u < used.size(); ++u) {
    const Eigen::Index row = 2 * static_cast<Eigen::Index>(u);
    const std::size_t k = static_cast<std::size_t>(match[used[u]]);
    const PredictedObservation pred = predict_observation(v, x_.segment<2>(slot(k)));
    h.block<2, 3>(row, 0) = pred.d_pose;
    h.block<2, 2>(row, slot(k)) = pred.d_point;
    r.block<2, 2>(row, row) = z[used[u]].noise;
    nu.segment<2>(row) = innovation(z[used[u]], pred.z);
  }
  const Eigen::MatrixXd ph = p_ * h.transpose();
  const Eigen::MatrixXd s = h * ph + r;
  const Eigen::MatrixXd k = ph * s.ldlt().solve(Eigen::MatrixXd::Identity(m, m));
  x_ += k * nu;
  x_(2) = normalize_angle(x_(2));
  // Joseph-free form, symmetrised: the local maps are short.
  p_ -= k * ph.transpose();
  p_ = 0.5 * (p_ + p_.transpose());
}

// EKF-SLAM augmentation with the inverse observation model.
void EkfFrontEnd::add_feature(const RangeBearing& z) {
  const Pose2 v = to_pose(x_.head<3>());
  const InitialisedPoint ip = point_from_observation(v, z.range, z.bearing);
  const Eigen::Index n = x_.size();
  x_.conservativeResize(n + 2);
  x_.segment<2>(n) = ip.point;
  p_.conservativeResize(n + 2, n + 2);
  const Eigen::MatrixXd cross = ip.d_pose * p_.topLeftCorner(3, n);
  p_.bottomLeftCorner(2, n) = cross;
  p_.topRightCorner(n, 2) = cross.transpose();
  p_.bottomRightCorner<2, 2>() =
      ip.d_pose * p_.topLeftCorner<3, 3>() * ip.d_pose.transpose() + ip.d_z * z.noise * ip.d_z.transpose();
  ids_.push_back(next_id_++);
  existence_of_.push_back(existence_.created());
}

void EkfFrontEnd::update_existence(const std::vector<int>& match) {
  std::vector<char> hit(ids_.size(), 0);
  for (int k : match) {
    if (k >= 0) hit[static_cast<std::size_t>(k)] = 1;
  }
  const Eigen::Vector2d here = x_.head<2>();
  const double view = options_.sensor.max_range - options_.existence.view_margin;
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    if (hit[k]) {
      existence_of_[k] = existence_.detected(existence_of_[k]);
    } else if ((x_.segment<2>(slot(k)) - here).norm() <= view) {
      existence_of_[k] = existence_.missed(existence_of_[k]);
    }
  }
  for (std::size_t k = ids_.size(); k-- > 0;) {
    if (existence_of_[k] < options_.existence.cull_threshold) remove_feature(k);
  }
}

void EkfFrontEnd::remove_feature(std::size_t k) {
  std::vector<int> keep;
  for (Eigen::Index i = 0; i < x_.size(); ++i) {
    if (i != slot(k) && i != slot(k) + 1) keep.push_back(static_cast<int>(i));
  }
  const Eigen::VectorXi idx = Eigen::Map<Eigen::VectorXi>(keep.data(), static_cast<Eigen::Index>(keep.size()));
  x_ = Eigen::VectorXd(x_(idx));
  p_ = Eigen::MatrixXd(p_(idx, idx));
  ids_.erase(ids_.begin() + static_cast<long>(k));
  existence_of_.erase(existence_of_.begin() + static_cast<long>(k));
}

PoseGaussian EkfFrontEnd::vehicle() const { return {to_pose(x_.head<3>()), p_.topLeftCorner<3, 3>()}; }

GaussianMap EkfFrontEnd::to_gaussian(double min_existence) {
  std::vector<int> keep = {0, 1, 2};
  GaussianMap g;
  for (std::size_t k = 0; k < ids_.size(); ++k) {
    if (existence_of_[k] <= min_existence) continue;
    keep.push_back(static_cast<int>(slot(k)));
    keep.push_back(static_cast<int>(slot(k)) + 1);
    g.ids.push_back(ids_[k]);
    g.existence.push_back(existence_of_[k]);
  }
  const Eigen::VectorXi idx = Eigen::Map<Eigen::VectorXi>(keep.data(), static_cast<Eigen::Index>(keep.size()));
  g.mean = x_(idx);
  g.covariance = p_(idx, idx);
  return g;
}

}  // namespace lookahead::slam::hybrid
