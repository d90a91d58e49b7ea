// SPDX-License-Identifier: MIT
// One particle's share of an RBPF update (Grisetti, Stachniss, Burgard 2007, sec. IV steps
// 1-3): scan-match, draw from the improved proposal (or from odometry when matching fails),
// multiply the weight, insert the scan. The grid RBPF runs it for every particle; SegSLAM runs
// the same step on each particle's submap ("the particle filter steps stay those of the RBPF").
#pragma once

#include <cstdint>
#include <random>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/rbpf/rbpf_options.hpp"
#include "lookahead/slam/rbpf/scan_matcher.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam {

/// The filter components a particle step reads (owned by the filter).
struct ParticleStepModels {
  const RbpfOptions& options;
  const OdometryMotionModel& motion;
  const LikelihoodFieldModel& likelihood;
  const ScanMatcher& matcher;
};

/// Steps 1-2 only: moves `pose` through the proposal and adds the weight factor, leaving the
/// map as it was (P-SLAM scores the hypotheses on m_{k-1} before the scan goes in). Returns
/// true when a warm particle's scan match failed. `estimate`, when given, receives the mean
/// of the improved proposal the pose was drawn from (the drawn pose where the motion model
/// proposed it): the pose to report, without the draw's noise.
bool draw_particle(const ParticleStepModels& models, const OccupancyGrid& map, Pose2& pose, double& log_weight,
                   const Pose2& u, const PreparedScan& prepared, bool warm, std::mt19937_64& rng,
                   Pose2* estimate = nullptr);

/// Moves `pose` by odometry increment `u` through the proposal, adds the weight factor to
/// `log_weight` (only when `warm`: a map with too few scans is not matched against) and
/// inserts `scan` into `map`. Returns true when a warm particle's scan match failed.
bool advance_particle(const ParticleStepModels& models, OccupancyGrid& map, Pose2& pose, double& log_weight,
                      const Pose2& u, const LaserScan& scan, const PreparedScan& prepared, bool warm,
                      std::mt19937_64& rng);

/// A reproducible, well-mixed seed for (run seed, update, particle): draws do not depend on
/// which thread runs which particle.
std::uint64_t mix_seed(std::uint64_t a, std::uint64_t b, std::uint64_t c);

}  // namespace lookahead::slam
