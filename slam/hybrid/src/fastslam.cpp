// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/fastslam.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "correspondence_vote.hpp"
#include "lookahead/slam/rbpf/particle_filter.hpp"
#include "moment_matching.hpp"
#include "pose_sampling.hpp"

namespace lookahead::slam::hybrid {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// The pose proposal of FastSLAM 2.0 as a Gaussian, refined one observation at a time.
struct Proposal {
  Pose2 mean;
  Matrix3 covariance;
};

// One candidate association of an observation, with what the proposal update needs.
struct Candidate {
  int landmark = -1;
  double likelihood = 0.0;
  Vector2 nu;
  Matrix23 d_pose;
  Matrix2 s;
};

Candidate evaluate(const Proposal& q, const Landmark& l, int index, const RangeBearing& z, double gate_chi2) {
  const PredictedObservation h = predict_observation(q.mean, l.mean);
  Candidate c;
  c.landmark = index;
  c.nu = innovation(z, h.z);
  c.d_pose = h.d_pose;
  c.s = h.d_pose * q.covariance * h.d_pose.transpose() + h.d_point * l.covariance * h.d_point.transpose() + z.noise;
  const double d2 = c.nu.dot(c.s.inverse() * c.nu);
  if (d2 > gate_chi2) return c;  // likelihood stays 0
  c.likelihood = std::exp(-0.5 * d2) / (kTwoPi * std::sqrt(c.s.determinant()));
  return c;
}

// EKF update of the pose proposal by an associated observation (the FastSLAM 2.0 proposal,
// in Kalman form so that a singular motion covariance needs no inverse).
void refine(Proposal& q, const Candidate& c) {
  const Eigen::Matrix<double, 3, 2> k = q.covariance * c.d_pose.transpose() * c.s.inverse();
  q.mean = to_pose(to_vector(q.mean) + k * c.nu);
  q.covariance = (Matrix3::Identity() - k * c.d_pose) * q.covariance;
  q.covariance = 0.5 * (q.covariance + q.covariance.transpose());
}

void update_landmark(Landmark& l, const Pose2& pose, const RangeBearing& z) {
  const PredictedObservation h = predict_observation(pose, l.mean);
  const Matrix2 s = h.d_point * l.covariance * h.d_point.transpose() + z.noise;
  const Matrix2 k = l.covariance * h.d_point.transpose() * s.inverse();
  l.mean += k * innovation(z, h.z);
  l.covariance = (Matrix2::Identity() - k * h.d_point) * l.covariance;
  l.covariance = 0.5 * (l.covariance + l.covariance.transpose());
}

}  // namespace

FastSlam::FastSlam(const HybridOptions& options, std::uint64_t seed)
    : options_(options), existence_(options.existence), rng_(seed) {
  if (options.fastslam.particles < 1) throw std::invalid_argument("fastslam.particles must be >= 1");
  restart();
}

void FastSlam::restart() {
  const double w = 1.0 / options_.fastslam.particles;
  particles_.assign(static_cast<std::size_t>(options_.fastslam.particles), Particle{Pose2{}, w, {}});
  has_pending_ = false;
}

void FastSlam::predict(const MotionStep& step) {
  if (has_pending_) {  // two controls without an observation: the first is plain motion
    for (auto& p : particles_) p.pose = sample_motion(p.pose, pending_, rng_);
  }
  pending_ = step;
  has_pending_ = true;
}

void FastSlam::observe(const std::vector<RangeBearing>& z) {
  std::vector<std::vector<Decision>> decisions(particles_.size());
  std::vector<double> log_factor(particles_.size());
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    log_factor[i] = update_particle(particles_[i], z, decisions[i]);
  }
  has_pending_ = false;
  const double top = *std::max_element(log_factor.begin(), log_factor.end());
  double total = 0.0;
  for (std::size_t i = 0; i < particles_.size(); ++i) {
    particles_[i].weight *= std::exp(log_factor[i] - top);
    total += particles_[i].weight;
  }
  for (auto& p : particles_) p.weight /= total;
  if (!z.empty()) vote_correspondences(particles_, decisions, next_id_);  // HybridSLAM sec. 3.1
  cull();
  resample_if_degenerate();
}

double FastSlam::update_particle(Particle& p, const std::vector<RangeBearing>& z, std::vector<Decision>& decisions) {
  const MotionStep step = has_pending_ ? pending_ : MotionStep{};
  Proposal q{p.pose.compose(step.delta), control_covariance(p.pose, step)};
  const auto& fo = options_.fastslam;
  const double r2 = fo.candidate_radius * fo.candidate_radius;
  const double p_new = fo.new_feature_likelihood;
  // An unexplained observation is spurious rather than new in the ratio of the clutter and
  // detection rates (both clamped, see ExistenceOptions).
  const double p_spurious = p_new * existence_.beta() / existence_.alpha();
  std::vector<char> used(p.landmarks.size(), 0);
  decisions.assign(z.size(), Decision{});
  std::vector<Candidate> candidates;
  double log_w = 0.0;
  for (std::size_t j = 0; j < z.size(); ++j) {
    const Vector2 seen = point_from_observation(q.mean, z[j].range, z[j].bearing).point;
    candidates.clear();
    double sum = p_new + p_spurious;
    for (std::size_t i = 0; i < p.landmarks.size(); ++i) {
      if (used[i] || (p.landmarks[i].mean - seen).squaredNorm() > r2) continue;
      Candidate c = evaluate(q, p.landmarks[i], static_cast<int>(i), z[j], fo.gate_chi2);
      if (c.likelihood <= 0.0) continue;
      sum += c.likelihood;
      candidates.push_back(c);
    }
    log_w += std::log(sum);  // DAS weight: the likelihood summed over the associations
    double pick = std::uniform_real_distribution<double>(0.0, sum)(rng_);
    Decision& d = decisions[j];
    d.kind = pick < p_spurious ? Decision::Kind::kSpurious : Decision::Kind::kCreated;
    pick -= p_spurious + p_new;
    for (const Candidate& c : candidates) {
      if (pick < 0.0) break;
      pick -= c.likelihood;
      if (pick < 0.0) {
        d = {Decision::Kind::kAssociated, c.landmark};
        used[static_cast<std::size_t>(c.landmark)] = 1;
        refine(q, c);
      }
    }
  }
  p.pose = sample_gaussian_pose(q.mean, q.covariance, rng_);
  for (std::size_t j = 0; j < z.size(); ++j) {
    Decision& d = decisions[j];
    if (d.kind == Decision::Kind::kAssociated) {
      Landmark& l = p.landmarks[static_cast<std::size_t>(d.landmark)];
      update_landmark(l, p.pose, z[j]);
      l.existence = existence_.detected(l.existence);
    } else if (d.kind == Decision::Kind::kCreated) {
      const InitialisedPoint ip = point_from_observation(p.pose, z[j].range, z[j].bearing);
      d.landmark = static_cast<int>(p.landmarks.size());
      p.landmarks.push_back({ip.point, ip.d_z * z[j].noise * ip.d_z.transpose(), existence_.created(), -1});
      used.push_back(1);
    }
  }
  apply_missed_detections(p, decisions);
  return log_w;
}

void FastSlam::apply_missed_detections(Particle& p, const std::vector<Decision>& decisions) const {
  std::vector<char> hit(p.landmarks.size(), 0);
  for (const Decision& d : decisions) {
    if (d.kind != Decision::Kind::kSpurious) hit[static_cast<std::size_t>(d.landmark)] = 1;
  }
  const double view = options_.sensor.max_range - options_.existence.view_margin;
  for (std::size_t i = 0; i < p.landmarks.size(); ++i) {
    Landmark& l = p.landmarks[i];
    if (hit[i] || std::hypot(l.mean.x() - p.pose.x, l.mean.y() - p.pose.y) > view) continue;
    l.existence = existence_.missed(l.existence);
  }
}

void FastSlam::cull() {
  const double floor = options_.existence.cull_threshold;
  for (auto& p : particles_) {
    auto& l = p.landmarks;
    l.erase(std::remove_if(l.begin(), l.end(), [&](const Landmark& m) { return m.existence < floor; }), l.end());
  }
}

// Selective low-variance resampling on the linear weights (Grisetti et al. 2007, sec. IV
// step 5, N_eff of eq. (20)); every drawn particle gets the weight 1/P.
void FastSlam::resample_if_degenerate() {
  std::vector<double> w;
  w.reserve(particles_.size());
  for (const auto& p : particles_) w.push_back(p.weight);
  if (!should_resample(effective_sample_size(w), options_.fastslam.resample_threshold, particles_.size())) return;
  const double equal = 1.0 / static_cast<double>(particles_.size());
  draw_particles(particles_, low_variance_resample(w, rng_), [&](Particle& p) { p.weight = equal; });
  ++resamplings_;
}

PoseGaussian FastSlam::vehicle() const { return moment_match_pose(particles_); }

GaussianMap FastSlam::to_gaussian(double min_existence) { return moment_match(particles_, min_existence, rng_); }

}  // namespace lookahead::slam::hybrid
