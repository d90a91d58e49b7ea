// SPDX-License-Identifier: MIT
// SegSLAM on 2D laser logs: Fairfield, Kantor, Wettergreen, "Segmented SLAM in
// three-dimensional environments", J. Field Robotics 27(1), 2010, SegSLAM sec. 4.1. Each particle
// is a pose plus its own open submap; prediction samples the pose with the RBPF's proposal
// and the submap among {same, new, match} (SegSLAM eq. (3)); weighting, resampling and map update are
// the RBPF's (rbpf/particle_step.hpp). The filter runs `lookahead_s` behind the newest scan
// so segmentation (SegSLAM eq. (13)-(17)) and matching (SegSLAM eq. (18)) can use the look-ahead window; the
// estimate is brought to the present by dead reckoning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <tuple>
#include <vector>

#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/rbpf/motion_model.hpp"
#include "lookahead/slam/rbpf/rbpf_options.hpp"
#include "lookahead/slam/rbpf/scan_matcher.hpp"
#include "lookahead/slam/segslam/grid_submap_ops.hpp"
#include "lookahead/slam/segslam/seg_map.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"
#include "lookahead/slam/sensor/laser_scan.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam::segslam {

using GridSubmap = Submap<OccupancyGrid, Pose2>;
using GridSegMap = SegMap<OccupancyGrid, Pose2>;

struct SegParticle {
  Pose2 pose;         ///< x_t in its submap's frame
  GridSubmap submap;  ///< the open submap theta_i it maps into
  double log_weight = 0.0;
  int submap_updates = 0;     ///< filter updates in the open submap
  double motion_error = 0.0;  ///< SegSLAM eq. (13)-(14), accumulated in the open submap [m]
  /// err_ICP of the match that opened the submap [m]; infinite for a fresh submap.
  double entry_error = std::numeric_limits<double>::infinity();
};

/// A re-entry: at `scan`, a particle moved into a copy of submap `candidate`.
struct MatchEvent {
  std::size_t scan = 0;
  std::size_t candidate = 0;
  double weight = 0.0;
};

struct SegSlamStatistics {
  std::size_t scans = 0, updates = 0, resamplings = 0, match_failures = 0;
  std::size_t segmentations = 0;   ///< particle submaps started fresh
  std::size_t matches = 0;         ///< particle submaps started as a match
  std::size_t match_attempts = 0;  ///< candidates matched by ICP
  std::size_t pruned = 0;          ///< non-viable submaps dropped
  std::size_t locked = 0;          ///< re-entered submaps locked (localisation only)
  std::size_t merged = 0;          ///< closed re-entered submaps merged into their parent
  std::vector<double> neff;
  std::vector<MatchEvent> match_events;
};

class SegSlam {
 public:
  SegSlam(const RbpfOptions& rbpf, const SegSlamOptions& options);

  /// Feeds one scan (in time order); updates run once the look-ahead window is full.
  void add_scan(const LaserScan& scan);
  /// Runs the updates still waiting for their window (the end of a log).
  void finish();

  [[nodiscard]] const std::vector<SegParticle>& particles() const { return particles_; }
  [[nodiscard]] const GridSegMap& segmap() const { return segmap_; }
  [[nodiscard]] std::size_t best_particle() const;
  /// Particle m's pose at its last update in the frame of the first submap (the odometry
  /// frame of the first scan), by SegSLAM eq. (11) with matches closing loops.
  [[nodiscard]] Pose2 global_pose(std::size_t m) const;
  /// The weighted mean of the particles' global poses, brought to the newest scan by dead
  /// reckoning (SegSLAM sec. 4.1, Estimate; SegSLAM sec. 5.2's loop-closure estimate).
  [[nodiscard]] Pose2 estimate() const;
  /// Particle m's reconstructed trajectory: (scan, pose in the first submap's frame) per update.
  [[nodiscard]] std::vector<std::pair<std::size_t, Pose2>> trajectory(std::size_t m) const;
  /// Particle m's pose at every scan fed so far: its trajectory, with scans between updates
  /// (and after the last one, the look-ahead tail) placed by dead reckoning.
  [[nodiscard]] std::vector<Pose2> trajectory_at_every_scan(std::size_t m) const;
  [[nodiscard]] const std::vector<LaserScan>& scans() const { return scans_; }
  [[nodiscard]] const SegSlamStatistics& statistics() const { return stats_; }
  [[nodiscard]] const RbpfOptions& rbpf_options() const { return rbpf_; }
  [[nodiscard]] const SegSlamOptions& options() const { return options_; }

 private:
  struct Transition;  // a particle's submap change, applied after the parallel step
  void initialize();
  void update(std::size_t scan);
  LookaheadWindow window_after(std::size_t scan) const;
  /// `window` builds the look-ahead window on first use (most updates neither score nor match).
  Transition predict_submap(SegParticle& p, const std::function<const LookaheadWindow&()>& window,
                            std::mt19937_64& rng);
  std::vector<WindowMatch> match_candidates(const SegParticle& p, const LookaheadWindow& w,
                                            std::vector<std::size_t>& ids, std::mt19937_64& rng);
  void store_closed(SegParticle& p, Transition& t);
  void resample_if_needed();

  /// cached_match, screened on the first copy of the candidate's segment (share_by_segment).
  WindowMatch screened_match(std::size_t candidate, const Pose2& guess, const LookaheadWindow& w,
                             const MatchingOptions& reach);
  /// Matches of this update by (candidate, guess rounded to 1 m / 0.1 rad): resampled
  /// particles share their history and ask for the same match.
  WindowMatch cached_match(std::size_t candidate, const Pose2& guess, const LookaheadWindow& w,
                           const MatchingOptions& reach);
  /// SegSLAM eq. (13)-(14) error accumulated since the robot left the candidate [m] (candidate_reach.hpp).
  [[nodiscard]] double error_since(std::size_t candidate) const;
  std::uint64_t localization_seed(const std::tuple<std::size_t, long, long, long>& key) const;

  RbpfOptions rbpf_;
  SegSlamOptions options_;
  OdometryMotionModel motion_;
  OccupancyGrid prototype_grid_;
  LikelihoodFieldModel likelihood_;
  ScanMatcher matcher_;
  std::vector<SegParticle> particles_;
  GridSegMap segmap_;
  std::vector<LaserScan> scans_;
  std::size_t next_pending_ = 0;               ///< the oldest scan not yet considered for an update
  std::size_t last_update_ = 0;                ///< the scan of the last filter update
  std::vector<double> motion_error_sum_{0.0};  ///< SegSLAM eq. (13)-(14) error accumulated up to each scan [m]
  std::mt19937_64 rng_;
  SegSlamStatistics stats_;
  std::mutex cache_mutex_;
  /// ICP targets of closed submaps (immutable once closed), prepared on first use.
  /// Both are filled by whichever thread asks first (compute_once.hpp).
  std::map<std::size_t, std::shared_future<std::shared_ptr<const GridMatchTarget>>> match_targets_;
  std::map<std::tuple<std::size_t, long, long, long>, std::shared_future<WindowMatch>> match_cache_;
};

}  // namespace lookahead::slam::segslam
