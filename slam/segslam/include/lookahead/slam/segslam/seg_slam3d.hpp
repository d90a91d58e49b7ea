// SPDX-License-Identifier: MIT
// SegSLAM on 3D range sweeps with copy-on-write evidence octrees: Fairfield, Kantor,
// Wettergreen, "Segmented SLAM in three-dimensional environments", J. Field Robotics 27(1),
// 2010, SegSLAM sec. 4-5. Each particle is a level pose (x, y, z, yaw; roll and pitch are the IMU's)
// plus its open octree submap; prediction samples the pose with the 3D RBPF's proposal
// (rbpf3d/motion3_model.hpp) and the submap among {same, new, match} (SegSLAM eq. (3), SegSLAM eq. (18));
// weighting and map update are the 3D RBPF's (octree_likelihood, ray_insertion). The
// SegMap, map samples, segmentation criterion, submap choice and trajectory reconstruction
// are the generic code of the 2D filter (seg_map.hpp, map_sampler.hpp, segmentation.hpp,
// submap_choice.hpp, trajectory_reconstruction.hpp) instantiated for EvidenceOctree + Pose4;
// the octree operations are in octree_submap_ops.hpp.
//
// Deviation: the filter loop is a sibling of the 2D SegSlam class, not one template with it:
// that class is written against laser scans and the 2D particle step; the graph code, the
// SegSLAM eq. (3)/13-14/18 functions and SegMap::merge_into_parent are shared. Locking and merging
// (SegSLAM sec. 6, the `locking:` options, off by default) follow the 2D filter: seg_slam3d_locking.cpp.
// Submap frames are level (x, y, z, yaw), and proximity winnowing also bounds the height
// difference (the garage's decks share x, y). A match is scored on the window's structure
// points and vetoed when they land in the candidate's free space (structure_fit.hpp), and
// SegSLAM eq. (18)'s p(tau^2), the proximity radius and the coarse search widen with the SegSLAM eq. (13)-(14)
// error since the candidate (candidate_reach.hpp); beyond that search's cap a wide search
// sized by SegSLAM eq. (18)'s sigma_tau is taken only when unambiguous (wide_reentry.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <tuple>
#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/rbpf3d/rbpf3d_options.hpp"
#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "lookahead/slam/segslam/map_sampler.hpp"
#include "lookahead/slam/segslam/match_attempt3.hpp"
#include "lookahead/slam/segslam/octree_submap_ops.hpp"
#include "lookahead/slam/segslam/seg_map.hpp"
#include "lookahead/slam/segslam/segment_picture.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"
#include "lookahead/slam/segslam/wide_reentry.hpp"
#include "lookahead/slam/sensor/range_sweep.hpp"

namespace lookahead::slam::segslam {

using OctreeSubmap = Submap<EvidenceOctree, Pose4>;
using OctreeSegMap = SegMap<EvidenceOctree, Pose4>;

/// What only the 3D filter needs besides the RBPF's and SegSLAM's options.
struct SegSlam3dExtras {
  /// A fresh submap weighs its sweeps by the other particles' mean factor for this many
  /// updates (it has only one sweep to compare against). >= 0.
  int warmup_updates = 1;
  /// Proximity winnowing also needs the robot within this height of the candidate's path
  /// [m] (the garage's decks are 3 m apart). > 0.
  double proximity_height = 1.0;
  /// End points of the look-ahead window scored by SegSLAM eq. (17) and the coarse search. >= 10.
  int window_points = 300;
  /// What a match's walls, columns and cars must show (structure_fit.hpp).
  StructureTestOptions structure;
  /// The wide, unambiguous re-entry search beyond that cap (wide_reentry.hpp).
  WideReentryOptions wide;
  /// Keep every candidate considered, with its outcome, in the statistics (debug log).
  bool record_attempts = false;
};

/// The SegSLAM options for 3D sweeps: the 2D defaults with the bins, ICP and SegSLAM eq. (18) scales
/// of 0.2 m voxels, and the look-ahead and periods of one sweep per second. Mirrored in
/// config/segslam3d/default.yaml (a test checks).
SegSlamOptions segslam3d_defaults();

struct SegSlam3dOptions {
  Rbpf3dOptions filter;
  SegSlamOptions segslam = segslam3d_defaults();
  SegSlam3dExtras extras;
};

struct SegParticle3 {
  Pose4 pose;           ///< x_t in its submap's frame
  OctreeSubmap submap;  ///< the open submap it maps into
  double log_weight = 0.0;
  int submap_updates = 0;       ///< filter updates in the open submap
  double motion_error = 0.0;    ///< SegSLAM eq. (13)-(14), accumulated in the open submap [m]
  int updates_since_match = 0;  ///< since the last matching attempt
  /// err_ICP of the match that opened the submap [m]; infinite for a fresh submap (locking).
  double entry_error = std::numeric_limits<double>::infinity();
  /// A wide re-entry found at the last attempt, checked at the next one (wide_reentry.hpp).
  std::optional<PendingReentry> pending;
};

/// One match a particle was offered (and, if `chosen`, took): enough to check it against
/// ground truth afterwards, when the candidate submap may have been pruned.
struct MatchEvent3 {
  std::size_t sweep = 0;
  std::size_t candidate = 0;
  double weight = 0.0;
  double icp_error = 0.0;         ///< SegSLAM eq. (18) err_ICP (structure points) [m]
  double all_points_error = 0.0;  ///< ICP's mean error over all points [m]
  double translation = 0.0;       ///< SegSLAM eq. (18) tau [m]
  Pose4 pose;                     ///< the re-entry pose, in the candidate's frame
  Pose4 guess;                    ///< the particle's pose placed there by the map sample
  StructureFit structure;         ///< the window's walls, columns and cars at `pose`
  /// The candidate's path pose (its own or an ancestor's, same frame) nearest to `pose`:
  /// reference.between(pose) is the match's claim about where the robot is now relative to
  /// where it was at reference_sweep.
  std::size_t reference_sweep = 0;
  Pose4 reference;
  bool chosen = false;
};

struct SegSlam3dStatistics {
  std::size_t sweeps = 0, updates = 0, resamplings = 0;
  std::size_t segmentations = 0, matches = 0, match_attempts = 0, pruned = 0;
  std::size_t match_requests = 0;  ///< candidate matches asked for; match_attempts of them searched
  std::size_t wide_attempts = 0;   ///< of match_attempts, wide searches (wide_reentry.hpp)
  /// Capped searches run (seg_slam3d_capped.cpp): each answers the distinct rounded guesses
  /// on one submap at one update, which match_attempts counts one by one.
  std::size_t capped_searches = 0;
  std::size_t locked = 0;          ///< re-entered submaps locked (localisation only, SegSLAM sec. 6)
  std::size_t locked_updates = 0;  ///< particle updates in a locked submap (no ray insertion)
  std::size_t merged = 0;          ///< closed re-entered submaps merged into their parent
  std::vector<double> neff;
  std::vector<MatchEvent3> match_events;  ///< the matches taken
  std::vector<MatchEvent3> match_offers;  ///< every match offered to a particle, taken or not
  std::vector<MatchAttempt3> attempts;    ///< every candidate considered (record_attempts only)
  double matching_seconds = 0;            ///< summed over threads: building targets, coarse search, ICP
  double wide_matching_seconds = 0;       ///< of matching_seconds, the wide searches' (wide_reentry.hpp)
};

class SegSlam3d {
 public:
  explicit SegSlam3d(const SegSlam3dOptions& options);

  /// Feeds one sweep (in time order); updates run once its look-ahead window is full.
  void add_sweep(const RangeSweep& sweep);
  /// Runs the updates still waiting for their window (the end of a log).
  void finish();

  [[nodiscard]] const std::vector<SegParticle3>& particles() const { return particles_; }
  [[nodiscard]] const OctreeSegMap& segmap() const { return segmap_; }
  [[nodiscard]] const SegSlam3dOptions& options() const { return options_; }
  [[nodiscard]] const SegSlam3dStatistics& statistics() const { return stats_; }
  [[nodiscard]] const std::vector<RangeSweep>& sweeps() const { return sweeps_; }
  [[nodiscard]] std::size_t best_particle() const;
  /// Particle m's pose at its last update in the first submap's frame (the odometry frame
  /// of the first sweep), by SegSLAM eq. (11) with matches closing loops.
  [[nodiscard]] Pose4 global_pose(std::size_t m) const;
  /// The weighted mean of the particles' global poses, brought to the newest sweep by dead
  /// reckoning (SegSLAM sec. 4.1; SegSLAM sec. 5.2's loop-closure estimate).
  [[nodiscard]] Pose4 estimate() const;
  /// Particle m's reconstructed trajectory (SegSLAM eq. (11)): (sweep, pose) per update.
  [[nodiscard]] std::vector<std::pair<std::size_t, Pose4>> trajectory(std::size_t m) const;
  /// The same at every sweep fed so far (the look-ahead tail by dead reckoning).
  [[nodiscard]] std::vector<Pose4> trajectory_at_every_sweep(std::size_t m) const;
  /// Top view, split by submap, with the re-entries (for pictures).
  [[nodiscard]] SegmentedPath segmented_trajectory(std::size_t m) const;

 private:
  struct Transition;
  struct SweepModel;  // one update's motion and measurement, shared by the particles
  /// A particle's wide search (wide_reentry.hpp), asked for during its prediction and run
  /// after it, with the other particles' of the same segment (seg_slam3d_wide.cpp).
  struct WideRequest {
    std::size_t candidate = 0;
    Pose4 guess;                   ///< the map sample's
    MatchingOptions options;       ///< its reach (wide_reach)
    std::size_t attempt = 0;       ///< index into the transition's attempts (record_attempts)
    double pending_weight = 0.0;   ///< SegSLAM eq. (18) weight of the pending re-entry confirmed this attempt
    Pose4 pose;                    ///< the particle's when it asked
    std::optional<Pose4> carried;  ///< the origin of the fresh submap the particle started since
    bool dropped = false;          ///< the particle took a match since: the re-entry goes nowhere
  };
  /// One wide search for the requests on copies of one segment (seg_slam3d_wide.cpp).
  struct WideSearch {
    std::size_t searched = 0;           ///< the submap searched (the segment's first copy)
    MatchingOptions options;            ///< the first member's, its reach rounded
    std::vector<std::size_t> members;   ///< the particles that asked, in order
    std::vector<WideRegion> regions;    ///< theirs, rounded
    std::vector<WindowMatch3> results;  ///< per member
  };
  void initialize(const RangeSweep& first);
  void update(std::size_t k);
  void run_pending(double lookahead_s);
  SweepWindow window_after(std::size_t sweep) const;
  /// SegSLAM eq. (13)-(14)/17 and, when the particle matches at this update, its candidates (and a
  /// confirmed pending re-entry); their capped searches run after, for all particles at once.
  Transition ask_submap(SegParticle3& p, const SweepWindow& w, std::mt19937_64& rng);
  /// SegSLAM eq. (3)'s draw among the matches offered, and the submap that follows.
  void choose_submap(SegParticle3& p, Transition& t, const SweepWindow& w, std::mt19937_64& rng);
  void advance(SegParticle3& p, const SweepModel& model, std::mt19937_64& rng) const;
  struct Candidate;  // a submap of the particle's map sample left for matching
  void ask_matches(SegParticle3& p, const SweepWindow& w, Transition& t, std::mt19937_64& rng);
  /// The candidates' capped results (a screen that matched fitted again to the particle's
  /// copy) and, where they found nothing, the wide request; into t's offers.
  void collect_matches(SegParticle3& p, const SweepWindow& w, Transition& t);
  /// One capped search for the requests on one submap (the segment's first copy) and height
  /// cell: each guess's rounded region answered from a shared grid (match_regions).
  struct CappedSearch {
    std::size_t searched = 0;
    MatchingOptions options;            ///< the searched submap's reach
    std::vector<LevelSubgrid> regions;  ///< distinct rounded guesses
    std::vector<WindowMatch3> results;  ///< per region
  };
  /// The capped searches the particles asked for, grouped, run as tasks, answers into screens.
  void run_capped_stage(std::vector<Transition>& transitions, const SweepWindow& w);
  void run_capped_search(CappedSearch& search, const SweepWindow& w);
  /// A guess rounded to the capped searches' lattice (two coarse steps in x, y and yaw, 0.5 m
  /// in height) with `reach`'s radius and angle: guesses in one cell share a search, and the
  /// grids of regions searched together coincide.
  [[nodiscard]] static LevelSubgrid capped_region(const Pose4& guess, const MatchingOptions& reach);
  std::vector<Candidate> winnow(const SegParticle3& p, std::size_t skip, std::vector<MatchAttempt3>& attempts,
                                std::mt19937_64& rng) const;
  void record(MatchAttempt3& a, std::size_t candidate, const WindowMatch3& m, bool wide) const;
  /// requests[i]: particle i's, or null.
  [[nodiscard]] std::vector<WideSearch> wide_searches(const std::vector<const WideRequest*>& requests) const;
  void run_wide_search(WideSearch& search, const SweepWindow& w);
  void apply_wide(SegParticle3& p, const WideRequest& request, WindowMatch3 m, std::vector<MatchAttempt3>& attempts);
  /// The wide searches the particles asked for, beside the steps of those particles
  /// (step_particle(i)), their results applied.
  void run_wide_stage(std::vector<Transition>& transitions, const SweepWindow& w,
                      const std::function<void(std::size_t)>& step_particle);
  [[nodiscard]] std::pair<std::size_t, Pose4> nearest_path_pose(std::size_t candidate, const Eigen::Vector3d& p) const;
  [[nodiscard]] MatchAttempt3 attempt_of(std::size_t candidate, const Pose4& guess, double path_distance,
                                         double chain_error, const std::optional<MatchingOptions>& wide) const;
  MatchEvent3 offer_of(std::size_t candidate, const Pose4& guess, const WindowMatch3& m) const;
  /// A candidate's capped result from its screen (run_capped_stage).
  WindowMatch3 capped_result(const Candidate& c, WindowMatch3 screen, const SweepWindow& w);
  WindowMatch3 cached_match(std::size_t candidate, const Pose4& guess, const SweepWindow& w);
  /// A capped search's key: the submap searched and its region's centre (x, y, z, yaw).
  using MatchKey = std::tuple<std::size_t, long, long, long, long>;
  [[nodiscard]] static MatchKey key_of(std::size_t candidate, const LevelSubgrid& region);
  /// match_window (or the SegSLAM eq. (19) localisation filter) from the region's centre.
  WindowMatch3 capped_search(std::size_t candidate, const LevelSubgrid& region, const MatchingOptions& o,
                             const SweepWindow& w);
  [[nodiscard]] std::uint64_t localization_seed(const MatchKey& key) const;
  std::shared_ptr<const OctreeMatchTarget> target_of(std::size_t candidate);
  std::optional<WindowMatch3> confirm_pending(SegParticle3& p, const SweepWindow& w,
                                              std::vector<MatchAttempt3>& attempts);
  [[nodiscard]] double error_since(std::size_t candidate) const;
  [[nodiscard]] MatchingOptions candidate_options(std::size_t candidate) const;
  [[nodiscard]] std::optional<MatchingOptions> wide_options(double chain_error) const;
  [[nodiscard]] std::vector<double> chain_errors(const std::vector<PlacedSubmap<Pose4>>& sample,
                                                 const SegParticle3& p) const;
  const SweepWindow& window_with_structure(const SweepWindow& w);
  void store_transitions(std::vector<Transition>& transitions);
  // Locking and merging (SegSLAM sec. 6; seg_slam3d_locking.cpp).
  [[nodiscard]] bool locks_on_entry(double entry_error, std::size_t candidate) const;
  void merge_if_registered(std::size_t id, double entry_error);
  /// The submap holding `id`'s evidence: `id` itself, or for a merged one its parent's.
  [[nodiscard]] std::size_t map_holder(std::size_t id) const;
  void prune();
  [[nodiscard]] int thread_count() const;

  SegSlam3dOptions options_;
  std::vector<SegParticle3> particles_;
  OctreeSegMap segmap_;
  std::vector<RangeSweep> sweeps_;
  std::vector<double> motion_error_sum_;  ///< SegSLAM eq. (13)-(14) error accumulated up to each updated sweep [m]
  std::size_t next_pending_ = 0;
  std::size_t last_update_ = 0;
  std::mt19937_64 rng_;
  SegSlam3dStatistics stats_;
  std::mutex cache_mutex_;
  std::map<std::size_t, std::shared_ptr<const OctreeMatchTarget>> targets_;
  std::map<MatchKey, WindowMatch3> match_cache_;
  std::mutex window_mutex_;
  std::optional<SweepWindow> matched_window_;  ///< this update's window with its structure
};

}  // namespace lookahead::slam::segslam
