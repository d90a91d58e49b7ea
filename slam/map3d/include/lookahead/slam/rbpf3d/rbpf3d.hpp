// SPDX-License-Identifier: MIT
// The 3D Rao-Blackwellized particle filter of SegSLAM sec. 2.2 (Fairfield et al. 2007):
// each particle is a pose and a copy-on-write evidence octree; the proposal is the dead-
// reckoning motion model; weights come from the scan likelihood; resampling is selective
// (only when N_eff drops). Resampled particles share their maps until they write.
//
// State: x, y, z and yaw per particle; roll and pitch are taken from the IMU. Deviation
// from a 6-DoF particle: the gravity-referenced IMU angles are far better than anything
// the filter could estimate, and the paper names yaw as the error that matters.
#pragma once

#include <memory>
#include <random>
#include <vector>

#include "lookahead/slam/rbpf3d/rbpf3d_options.hpp"
#include "lookahead/slam/sensor/range_sweep.hpp"

namespace lookahead::slam {

struct Trajectory3Node {
  Pose3 pose;
  std::shared_ptr<const Trajectory3Node> parent;

  Trajectory3Node(const Pose3& p, std::shared_ptr<const Trajectory3Node> up) : pose(p), parent(std::move(up)) {}
  ~Trajectory3Node();  // unlinks the chain iteratively (no deep recursion)
  Trajectory3Node(const Trajectory3Node&) = delete;
  Trajectory3Node& operator=(const Trajectory3Node&) = delete;
};

struct Particle3 {
  Pose3 pose = Pose3::Identity();
  EvidenceOctree map;
  double log_weight = 0.0;
  std::shared_ptr<const Trajectory3Node> trajectory;
};

struct Rbpf3dStatistics {
  std::size_t sweeps = 0;
  std::size_t resamplings = 0;
  std::vector<double> neff;           ///< after each weighted update
  double predict_weight_seconds = 0;  ///< wall time in motion + likelihood
  double insert_seconds = 0;          ///< wall time in ray insertion
};

class Rbpf3d {
 public:
  explicit Rbpf3d(const Rbpf3dOptions& options);

  /// One filter step per sweep: predict, weight, maybe resample, insert.
  void add_sweep(const RangeSweep& sweep);

  [[nodiscard]] const std::vector<Particle3>& particles() const { return particles_; }
  [[nodiscard]] const Rbpf3dOptions& options() const { return options_; }
  [[nodiscard]] const Rbpf3dStatistics& statistics() const { return stats_; }
  [[nodiscard]] std::size_t best_particle() const;
  /// Weighted mean of the particle positions (the paper's estimate, section 5.2).
  [[nodiscard]] Eigen::Vector3d mean_position() const;
  /// Poses of one particle, one per sweep, oldest first.
  [[nodiscard]] std::vector<Pose3> trajectory(std::size_t particle) const;

 private:
  void predict_and_weigh(const RangeSweep& sweep);
  void resample_if_needed();
  void insert(const RangeSweep& sweep);
  [[nodiscard]] int thread_count() const;

  Rbpf3dOptions options_;
  std::vector<Particle3> particles_;
  Pose3 last_odometry_ = Pose3::Identity();
  std::mt19937_64 rng_;
  Rbpf3dStatistics stats_;
};

}  // namespace lookahead::slam
