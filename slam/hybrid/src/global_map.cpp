// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/global_map.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "jcbb.hpp"
#include "lookahead/slam/hybrid/motion_step.hpp"

namespace lookahead::slam::hybrid {

LocalToGlobal local_to_global(const Pose2& origin, const Eigen::VectorXd& local) {
  const Eigen::Index n = local.size();
  const double c = std::cos(origin.theta), s = std::sin(origin.theta);
  Eigen::Matrix2d rot;
  rot << c, -s, s, c;
  LocalToGlobal g{Eigen::VectorXd(n), Eigen::MatrixXd::Zero(n, 3), Eigen::MatrixXd::Zero(n, n)};
  for (Eigen::Index at = 0; at < n; at += at == 0 ? 3 : 2) {
    const Eigen::Vector2d p = local.segment<2>(at);  // the vehicle's position, or a feature
    g.value.segment<2>(at) = Eigen::Vector2d(origin.x, origin.y) + rot * p;
    g.d_origin.block<2, 2>(at, 0).setIdentity();
    g.d_origin(at, 2) = -s * p.x() - c * p.y();
    g.d_origin(at + 1, 2) = c * p.x() - s * p.y();
    g.d_local.block<2, 2>(at, at) = rot;
  }
  g.value(2) = normalize_angle(origin.theta + local(2));
  g.d_origin(2, 2) = 1.0;
  g.d_local(2, 2) = 1.0;
  return g;
}

GlobalMap::GlobalMap(const FusionOptions& options, const Pose2& start)
    : options_(options), mean_(to_vector(start)), covariance_(Eigen::MatrixXd::Zero(3, 3)), joining_(start) {}

Pose2 GlobalMap::origin() const { return to_pose(mean_.head<3>()); }

Eigen::Vector2d GlobalMap::feature(std::size_t k) const {
  return mean_.segment<2>(3 + 2 * static_cast<Eigen::Index>(k));
}

Eigen::Matrix2d GlobalMap::feature_covariance(std::size_t k) const {
  const Eigen::Index at = 3 + 2 * static_cast<Eigen::Index>(k);
  return covariance_.block<2, 2>(at, at);
}

PoseGaussian GlobalMap::compose(const PoseGaussian& local) const {
  Eigen::VectorXd l = to_vector(local.mean);
  const LocalToGlobal g = local_to_global(origin(), l);
  const Eigen::Matrix3d jo = g.d_origin.topRows<3>(), jl = g.d_local.topLeftCorner<3, 3>();
  return {to_pose(g.value.head<3>()),
          jo * covariance_.topLeftCorner<3, 3>() * jo.transpose() + jl * local.covariance * jl.transpose()};
}

// HybridSLAM sec. 4: x+ = [x-; g(v-, x_L)] with
// P+ = [P-, P-_{:v} dg_v^T; dg_v P-_{v:}, dg_v P_vv dg_v^T + dg_z P_L dg_z^T].
// With `relinearise` (the default) the augmentation below only serves the association test.
void GlobalMap::augment(const GaussianMap& local) {
  const LocalToGlobal g = local_to_global(origin(), local.mean);
  const Eigen::Index old_n = mean_.size(), add = g.value.size();
  Eigen::VectorXd x(old_n + add);
  x << mean_, g.value;
  Eigen::MatrixXd p(old_n + add, old_n + add);
  p.topLeftCorner(old_n, old_n) = covariance_;
  const Eigen::MatrixXd cross = g.d_origin * covariance_.topRows<3>();  // dg_v [P_vv P_vm]
  p.bottomLeftCorner(add, old_n) = cross;
  p.topRightCorner(old_n, add) = cross.transpose();
  p.bottomRightCorner(add, add) = g.d_origin * covariance_.topLeftCorner<3, 3>() * g.d_origin.transpose() +
                                  g.d_local * local.covariance * g.d_local.transpose();
  mean_ = std::move(x);
  covariance_ = std::move(p);
}

FusionReport GlobalMap::fuse(const GaussianMap& local) {
  const std::size_t old_features = features();
  augment(local);
  FusionReport report;
  report.local_features = static_cast<int>(local.features());
  // After augmentation the state is [v-, old features, v_new, new features].
  const std::size_t first_new = old_features + 1;  // in 2-slots after the 3 of v-, see at()
  const std::vector<int> match = associate(first_new, local.features(), report);
  const auto at = [&](std::size_t feature_slot) { return 3 + 2 * feature_slot + 1; };  // +1: v_new's third entry
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t k = 0; k < match.size(); ++k) {
    if (match[k] >= 0) pairs.emplace_back(at(first_new + k), 3 + 2 * static_cast<std::size_t>(match[k]));
  }
  report.fusion_nis = fuse_pairs(pairs);
  // Remove the fused copies and the old origin; the new vehicle pose moves to the front.
  std::vector<Eigen::Index> drop = {0, 1, 2};
  for (const auto& [new_at, old_at] : pairs) {
    drop.push_back(static_cast<Eigen::Index>(new_at));
    drop.push_back(static_cast<Eigen::Index>(new_at) + 1);
  }
  const Eigen::Index v_new = 3 + 2 * static_cast<Eigen::Index>(old_features);
  remove_states(drop);  // v_new now sits where the old features end
  const Eigen::Index vn = v_new - 3;
  std::vector<int> order;
  for (int i = 0; i < 3; ++i) order.push_back(static_cast<int>(vn) + i);
  for (Eigen::Index i = 0; i < mean_.size(); ++i) {
    if (i < vn || i >= vn + 3) order.push_back(static_cast<int>(i));
  }
  const Eigen::VectorXi idx = Eigen::Map<Eigen::VectorXi>(order.data(), static_cast<Eigen::Index>(order.size()));
  mean_ = Eigen::VectorXd(mean_(idx));
  covariance_ = Eigen::MatrixXd(covariance_(idx, idx));
  mean_(2) = normalize_angle(mean_(2));
  report.associated = static_cast<int>(pairs.size());
  if (options_.relinearise) relinearise(local, match, old_features);
  return report;
}

// Deviation (beyond the paper; `relinearise`): the EKF above linearises g once, at the
// origin's estimate of the moment, and never again. Local maps linearised at different
// points add up to heading information no local map holds (the EKF-SLAM inconsistency of
// Bailey et al. 2006; HybridSLAM sec. 5.4), so the global heading std shrinks while its
// error stays. Re-solving all local maps together by Gauss-Newton (iterated SLSJF, Huang,
// Wang & Dissanayake 2008) evaluates every Jacobian at one point, the current solution, so
// the joined information keeps the rotation structure of each local map. The pairs are those
// the EKF step chose (JCBB); the EKF result seeds the solver.
void GlobalMap::relinearise(const GaussianMap& local, const std::vector<int>& match, std::size_t old_features) {
  std::vector<Eigen::Vector2d> new_guess;
  for (std::size_t k = old_features; k < features(); ++k) new_guess.push_back(feature(k));
  joining_.add(local, match, origin(), new_guess);
  joining_.solve(options_.relinearise_iterations);
  joining_.marginal(mean_, covariance_);
}

// JCBB between the new features (slots first_new..) and the old ones (slots 0..first_new-2):
// the innovation of a pair is the difference theta_new - theta_old. Deviation: the test adds
// association_sigma^2 I to its covariance (the fusion itself stays zero-noise, HybridSLAM eq. (10)). A
// FastSLAM local map is overconfident about its features relative to its vehicle (the
// particles lose path diversity within a local map); without the floor, copies of one
// feature a few centimetres apart failed the test and the map filled with duplicates.
std::vector<int> GlobalMap::associate(std::size_t first_new, std::size_t count, FusionReport& report) const {
  const std::size_t old_count = first_new - 1;
  const Eigen::Index n = mean_.size();
  const double gate = chi2_quantile(2, options_.jcbb_confidence);
  const double floor = options_.association_sigma * options_.association_sigma;
  const Eigen::Matrix2d noise = floor * Eigen::Matrix2d::Identity();
  std::vector<PairingCandidate> candidates;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Index a = static_cast<Eigen::Index>(3 + 2 * (first_new + i) + 1);
    for (std::size_t j = 0; j < old_count; ++j) {
      const Eigen::Index b = static_cast<Eigen::Index>(3 + 2 * j);
      const Eigen::Vector2d nu = mean_.segment<2>(a) - mean_.segment<2>(b);
      const Eigen::Matrix2d s = covariance_.block<2, 2>(a, a) + covariance_.block<2, 2>(b, b) -
                                covariance_.block<2, 2>(a, b) - covariance_.block<2, 2>(b, a) + noise;
      if (nu.dot(s.ldlt().solve(nu)) > gate) continue;
      PairingCandidate c{static_cast<int>(i), static_cast<int>(j), nu, Eigen::MatrixXd::Zero(2, n), noise};
      c.jacobian.block<2, 2>(0, a).setIdentity();
      c.jacobian.block<2, 2>(0, b) = -Eigen::Matrix2d::Identity();
      candidates.push_back(std::move(c));
    }
  }
  const JcbbResult r =
      jcbb(static_cast<int>(count), candidates, covariance_, options_.jcbb_confidence, options_.jcbb_max_nodes);
  report.search_truncated = r.search_truncated;
  return r.target_of;
}

// HybridSLAM eq. (10): the zero-noise observation theta_a - theta_b = 0 of every pair at once.
double GlobalMap::fuse_pairs(const std::vector<std::pair<std::size_t, std::size_t>>& pairs) {
  if (pairs.empty()) return 0.0;
  const Eigen::Index m = 2 * static_cast<Eigen::Index>(pairs.size()), n = mean_.size();
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m, n);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Eigen::Index row = 2 * static_cast<Eigen::Index>(k);
    h.block<2, 2>(row, static_cast<Eigen::Index>(pairs[k].first)).setIdentity();
    h.block<2, 2>(row, static_cast<Eigen::Index>(pairs[k].second)) -= Eigen::Matrix2d::Identity();
  }
  const Eigen::VectorXd nu = -(h * mean_);  // z_f = 0
  const Eigen::MatrixXd ph = covariance_ * h.transpose();
  const Eigen::MatrixXd s = h * ph;
  const Eigen::LDLT<Eigen::MatrixXd> s_ldlt(s);
  const Eigen::MatrixXd k = ph * s_ldlt.solve(Eigen::MatrixXd::Identity(m, m));
  mean_ += k * nu;
  covariance_ -= k * ph.transpose();
  covariance_ = 0.5 * (covariance_ + covariance_.transpose());
  return nu.dot(s_ldlt.solve(nu));
}

void GlobalMap::remove_states(std::vector<Eigen::Index> indices) {
  std::sort(indices.begin(), indices.end());
  std::vector<int> keep;
  for (Eigen::Index i = 0; i < mean_.size(); ++i) {
    if (!std::binary_search(indices.begin(), indices.end(), i)) keep.push_back(static_cast<int>(i));
  }
  const Eigen::VectorXi idx = Eigen::Map<Eigen::VectorXi>(keep.data(), static_cast<Eigen::Index>(keep.size()));
  mean_ = Eigen::VectorXd(mean_(idx));
  covariance_ = Eigen::MatrixXd(covariance_(idx, idx));
}

}  // namespace lookahead::slam::hybrid
