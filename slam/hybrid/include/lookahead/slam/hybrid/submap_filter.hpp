// SPDX-License-Identifier: MIT
// The sub-mapping filter of HybridSLAM (Brooks & Bailey, HybridSLAM sec. 4, Fig. 1): a local front-end
// maps in the frame of the last fusion pose; every `period` seconds its Gaussian (features
// with existence above the threshold) is fused into the EKF global map and a new local map
// starts at the vehicle. With a FastSLAM front-end this is HYBRID, with an EKF front-end
// the paper's EKF baseline, and with fusion off it is pure FastSLAM (FASTSLAM).
#pragma once

#include <memory>
#include <vector>

#include "lookahead/slam/hybrid/global_map.hpp"
#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/local_front_end.hpp"

namespace lookahead::slam::hybrid {

/// A feature of the final map, in the global frame.
struct MapFeature {
  Eigen::Vector2d mean;
  Eigen::Matrix2d covariance;
};

class SubmapFilter {
 public:
  /// `fuse` = false never fuses: the front-end alone (pure FastSLAM over the whole run).
  SubmapFilter(std::unique_ptr<LocalFrontEnd> front_end, const HybridOptions& options, const Pose2& start, bool fuse);

  /// One time step: control, observations, and a fusion when the rule says so.
  void step(const MotionStep& control, const std::vector<RangeBearing>& observations);
  /// Fuses what the local map holds (the end of a run).
  void finish();

  /// The vehicle's global pose: local and global estimates composed (the paper's Fig. 3
  /// estimate "based on both the local and global maps at every iteration").
  [[nodiscard]] PoseGaussian vehicle() const;
  [[nodiscard]] std::vector<MapFeature> feature_map();
  [[nodiscard]] const GlobalMap& global_map() const { return global_; }
  [[nodiscard]] const LocalFrontEnd& front_end() const { return *front_; }
  [[nodiscard]] int fusions() const { return fusions_; }
  [[nodiscard]] int associated_at_fusion() const { return associated_; }
  [[nodiscard]] const FusionReport& last_fusion() const { return last_report_; }
  /// The local map handed over at the last fusion, in its own frame (diagnostic traces).
  [[nodiscard]] const GaussianMap& last_local_map() const { return last_local_; }

 private:
  [[nodiscard]] bool fusion_due() const;
  void fuse_now();

  std::unique_ptr<LocalFrontEnd> front_;
  HybridOptions options_;
  GlobalMap global_;
  bool fuse_;
  double age_ = 0.0;  ///< seconds since the local map started
  int fusions_ = 0, associated_ = 0;
  FusionReport last_report_;
  GaussianMap last_local_;
};

}  // namespace lookahead::slam::hybrid
