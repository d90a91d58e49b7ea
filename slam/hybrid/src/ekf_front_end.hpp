// SPDX-License-Identifier: MIT
// The EKF local mapper: the front-end of the paper's EKF baseline (HybridSLAM sec. 5.1,
// filter 2). EKF-SLAM in the local frame with per-scan joint-compatibility association
// (JCBB), unmatched observations initialised as new features, and the same probability of
// existence (HybridSLAM eq. (11)) and culling as the FastSLAM front-end.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "lookahead/slam/hybrid/feature_existence.hpp"
#include "lookahead/slam/hybrid/hybrid_options.hpp"
#include "lookahead/slam/hybrid/local_front_end.hpp"

namespace lookahead::slam::hybrid {

class EkfFrontEnd final : public LocalFrontEnd {
 public:
  explicit EkfFrontEnd(const HybridOptions& options);

  void predict(const MotionStep& step) override;
  void observe(const std::vector<RangeBearing>& observations) override;
  [[nodiscard]] PoseGaussian vehicle() const override;
  [[nodiscard]] GaussianMap to_gaussian(double min_existence) override;
  void restart() override;

  [[nodiscard]] std::size_t features() const { return ids_.size(); }

 private:
  std::vector<int> associate(const std::vector<RangeBearing>& z) const;
  void update(const std::vector<RangeBearing>& z, const std::vector<int>& match);
  void add_feature(const RangeBearing& z);
  void update_existence(const std::vector<int>& match);
  void remove_feature(std::size_t k);

  HybridOptions options_;
  FeatureExistence existence_;
  Eigen::VectorXd x_;
  Eigen::MatrixXd p_;
  std::vector<long> ids_;
  std::vector<double> existence_of_;
  long next_id_ = 0;
};

}  // namespace lookahead::slam::hybrid
