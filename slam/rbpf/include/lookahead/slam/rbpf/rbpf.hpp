// SPDX-License-Identifier: MIT
// Rao-Blackwellized particle filter for grid SLAM with the improved proposal and selective
// resampling: Grisetti, Stachniss, Burgard, "Improved techniques for grid mapping with
// Rao-Blackwellized particle filters", IEEE T-RO 23(1), 2007, sec. III-IV.
#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include "lookahead/slam/rbpf/hypothesis_weight.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/rbpf/particle.hpp"
#include "lookahead/slam/rbpf/rbpf_options.hpp"
#include "lookahead/slam/rbpf/scan_matcher.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

struct RbpfStatistics {
  std::size_t scans = 0;
  std::size_t updates = 0;  ///< scans that ran the filter (motion threshold met)
  std::size_t resamplings = 0;
  std::size_t match_failures = 0;  ///< particle updates that fell back to odometry
  std::size_t particle_updates = 0;
  std::vector<double> neff;  ///< N_eff after each update
  // P-SLAM (only counted when prediction is enabled)
  std::size_t hypotheses_added = 0;
  std::size_t predicted_updates = 0;    ///< updates with enough end points on a hypothesis
  std::size_t prediction_used = 0;      ///< ... whose S2 entered the weights
  std::size_t prediction_rejected = 0;  ///< ... dropped by the hit-ratio recovery rule (P-SLAM eq. (23))
};

class Rbpf {
 public:
  explicit Rbpf(const RbpfOptions& options);

  /// Feeds one scan (in time order). Returns true when the filter ran an update on it.
  bool add_scan(const LaserScan& scan);

  /// P-SLAM: a new hypothesis, predicted on the best particle's map. Every particle gets it
  /// moved by its pose relative to the best particle (sec. IV-B); the oldest is dropped
  /// beyond prediction.max_hypotheses. Ignored when prediction is disabled.
  void add_hypothesis(std::shared_ptr<const HypothesisMap> hypothesis);
  void clear_hypotheses();
  [[nodiscard]] const std::vector<std::shared_ptr<const HypothesisMap>>& hypotheses() const { return hypotheses_; }

  [[nodiscard]] const std::vector<Particle>& particles() const { return particles_; }
  [[nodiscard]] std::size_t best_particle() const;
  /// The best particle's pose for every scan added so far: at an update the mean of the
  /// proposal its pose was drawn from (Grisetti et al. 2007, eq. 12). A scan between updates
  /// is placed where it matched on the best particle's map (else by odometry), with the
  /// correction the next update makes spread along the way (interpolated_trajectory.hpp).
  [[nodiscard]] std::vector<Pose2> best_trajectory() const;
  /// The best particle's estimate of the pose at the latest scan (its last drawn pose, the
  /// one its map was built with, moved by the scans matched since): what a robot in the loop
  /// plans from on that map.
  [[nodiscard]] Pose2 current_pose() const;
  /// The weighted mean of the particles' poses (circular mean of the headings), moved by the
  /// motion matched since the last update: the "final particle filter pose" of the SegSLAM paper's
  /// Table II (Fairfield et al. 2010), which SegSlam::estimate() gives for SegSLAM.
  [[nodiscard]] Pose2 mean_pose() const;
  [[nodiscard]] const std::vector<double>& timestamps() const { return timestamps_; }
  [[nodiscard]] const std::vector<Pose2>& odometry() const { return odometry_; }
  [[nodiscard]] const RbpfStatistics& statistics() const { return stats_; }
  [[nodiscard]] const RbpfOptions& options() const { return options_; }

 private:
  void initialize(const LaserScan& scan);
  bool motion_threshold_met(const LaserScan& scan) const;
  void track_between_updates(const LaserScan& scan);
  [[nodiscard]] std::optional<Pose2> track_on(const Particle& p, const Pose2& guess, const LaserScan& scan) const;
  void update_particle(Particle& p, const Pose2& u, const LaserScan& scan, const PreparedScan& prepared,
                       std::mt19937_64& rng, bool& failed, HypothesisScore& predicted) const;
  void update_particles(const LaserScan& scan);
  void apply_hypothesis_weights(const std::vector<HypothesisScore>& scores);
  void resample_if_needed();

  RbpfOptions options_;
  OdometryMotionModel motion_;
  OccupancyGrid prototype_grid_;
  LikelihoodFieldModel likelihood_;
  ScanMatcher matcher_;
  std::vector<Particle> particles_;
  std::vector<Pose2> since_update_;    ///< per scan: pose relative to the best particle's drawn pose
  std::vector<Pose2> since_estimate_;  ///< per scan: pose relative to its trajectory's last node
  std::vector<bool> tracked_;          ///< per scan: placed by matching between updates
  std::vector<std::shared_ptr<const HypothesisMap>> hypotheses_;
  std::mt19937_64 rng_;
  Pose2 last_update_odometry_;
  std::vector<double> timestamps_;
  std::vector<Pose2> odometry_;
  RbpfStatistics stats_;
};

}  // namespace lookahead::slam
