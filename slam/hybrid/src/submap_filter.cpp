// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/submap_filter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lookahead::slam::hybrid {

SubmapFilter::SubmapFilter(std::unique_ptr<LocalFrontEnd> front_end, const HybridOptions& options, const Pose2& start,
                           bool fuse)
    : front_(std::move(front_end)), options_(options), global_(options.fusion, start), fuse_(fuse) {
  if (fuse && !(options.fusion.period > 0.0)) throw std::invalid_argument("fusion.period must be > 0");
}

void SubmapFilter::step(const MotionStep& control, const std::vector<RangeBearing>& observations) {
  MotionStep c = control;
  const double root_dt = std::sqrt(std::max(control.dt, 0.0));
  const ProcessNoiseFloor& f = options_.process_floor;
  c.sigma = c.sigma.cwiseMax(Vector3(f.xy * root_dt, f.xy * root_dt, f.theta * root_dt));
  front_->predict(c);
  front_->observe(observations);
  age_ += control.dt;
  if (fuse_ && fusion_due()) fuse_now();
}

// HybridSLAM sec. 5.1: fuse every `period` seconds.
bool SubmapFilter::fusion_due() const { return age_ + 1e-9 >= options_.fusion.period; }

void SubmapFilter::fuse_now() {
  last_local_ = front_->to_gaussian(options_.existence.fuse_threshold);
  last_report_ = global_.fuse(last_local_);
  associated_ += last_report_.associated;
  front_->restart();
  age_ = 0.0;
  ++fusions_;
}

void SubmapFilter::finish() {
  if (fuse_ && age_ > 0.0) fuse_now();
}

PoseGaussian SubmapFilter::vehicle() const { return global_.compose(front_->vehicle()); }

std::vector<MapFeature> SubmapFilter::feature_map() {
  std::vector<MapFeature> out;
  if (fuse_) {
    for (std::size_t k = 0; k < global_.features(); ++k) {
      out.push_back({global_.feature(k), global_.feature_covariance(k)});
    }
    return out;
  }
  // Pure FastSLAM: its one local map, brought to the global frame of the start pose.
  const GaussianMap local = front_->to_gaussian(options_.existence.fuse_threshold);
  const LocalToGlobal g = local_to_global(global_.origin(), local.mean);
  const Eigen::MatrixXd cov = g.d_local * local.covariance * g.d_local.transpose();
  for (std::size_t k = 0; k < local.features(); ++k) {
    const Eigen::Index at = 3 + 2 * static_cast<Eigen::Index>(k);
    out.push_back({g.value.segment<2>(at), cov.block<2, 2>(at, at)});
  }
  return out;
}

}  // namespace lookahead::slam::hybrid
