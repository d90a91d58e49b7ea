// SPDX-License-Identifier: MIT
// The map-type-specific operations SegSLAM needs, for the 2D copy-on-write occupancy grid.
// SegMap, map sampling, trajectory reconstruction, segmentation and the SegSLAM eq. (3)/(18) choice are
// generic; a 3D octree plugs in by providing the same operations for its map and pose:
//   copy                   Map's copy constructor (copy-on-write, the child stores changes)
//   insert / score scan    the RBPF particle step (rbpf/particle_step.hpp here)
//   predictive_score       SegSLAM eq. (17) on the look-ahead window
//   has_observed_near      spatial-proximity winnowing (SegSLAM sec. 4.5.1)
//   match_window           ICP of the window's binned points onto a candidate (SegSLAM sec. 4.5)
//   MapCanvas              a map sample's submaps in one map, for entropy (SegSLAM eq. (20)-(22))
//   add_child_evidence     merging a re-entered submap into its parent (SegSLAM sec. 6)
#pragma once

#include <cstdint>
#include <vector>

#include "lookahead/slam/geometry/pose2.hpp"
#include "lookahead/slam/grid/occupancy_grid.hpp"
#include "lookahead/slam/io/map_io.hpp"
#include "lookahead/slam/segslam/binned_icp.hpp"
#include "lookahead/slam/segslam/coarse_search.hpp"
#include "lookahead/slam/segslam/near_field.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"
#include "lookahead/slam/sensor/likelihood_field_model.hpp"

namespace lookahead::slam::segslam {

/// A look-ahead window's scans, each with its dead-reckoned pose relative to the robot at
/// the window's first scan.
struct LookaheadWindow {
  std::vector<PreparedScan> scans;
  std::vector<Pose2> relative_poses;
  Points2 cloud;  ///< every end point in the first scan's robot frame, binned
};

/// SegSLAM eq. (17): the mean share of the window's end points that `map` explains (within one
/// hit distance of an obstacle) when the robot is at `pose` at the window's start.
double predictive_score(const OccupancyGrid& map, const Pose2& pose, const LookaheadWindow& window,
                        const LikelihoodFieldModel& likelihood);

/// SegSLAM sec. 4.5.1 spatial proximity: does `map` hold observed cells within `radius` of (x, y)?
bool has_observed_near(const OccupancyGrid& map, double x, double y, double radius);

struct WindowMatch {
  bool ok = false;
  Pose2 pose;                ///< the robot at the window's start, in the candidate's frame
  double icp_error = 0.0;    ///< [m]
  double translation = 0.0;  ///< tau_m: distance from the guess [m]
  double weight = 0.0;       ///< SegSLAM eq. (18) (or SegSLAM eq. (19))
  /// SegSLAM eq. (19)'s p(|Sigma_X|) for a localisation-filter match; 1 for ICP.
  double spread_factor = 1.0;
};

/// The ICP target of a submap: its obstacle cells, binned ("octree-binned point clouds").
IcpTarget icp_target_of(const OccupancyGrid& map, const MatchingOptions& options);

/// The coarse search's pose grid on `map`: +-search_radius in steps of most of the distance
/// field's radius, +-search_angle in 0.05 rad.
PoseGrid coarse_pose_grid(const OccupancyGrid& map, const MatchingOptions& options);

/// What matching needs of a closed submap, built once per candidate: its near-obstacle field
/// with the coarse search's bounds, its hit field (likelihood.hit_ratio's hits, for the fine
/// search), and its ICP target.
struct GridMatchTarget {
  NearField near;
  NearField hits;
  IcpTarget icp;
};
GridMatchTarget match_target_of(const OccupancyGrid& map, const MatchingOptions& options,
                                const LikelihoodFieldModel& likelihood);

/// SegSLAM sec. 4.5: matches the window onto `candidate` (prepared as `target`) from `guess` (the robot in the
/// candidate's frame as the map sample places it): a coarse search on the candidate's distance field seeds ICP on
/// binned points; the result is weighted by SegSLAM eq. (18).
WindowMatch match_window(const OccupancyGrid& candidate, const GridMatchTarget& target, const LookaheadWindow& window,
                         const Pose2& guess, const MatchingOptions& options);

/// SegSLAM sec. 4.5.2, SegSLAM eq. (19): matches the window onto `candidate` with a separate localisation
/// particle filter started around `guess` (spread over the coarse-search extent) and run over
/// the window's scans; weighted by p(err_X) p(|Sigma_X|) p(tau^2), with err_X the RMS distance
/// of the window's points to the candidate's obstacles at the filter's mean pose.
WindowMatch localize_window(const OccupancyGrid& candidate, const LookaheadWindow& window, const Pose2& guess,
                            const MatchingOptions& options, const LikelihoodFieldModel& likelihood, std::uint64_t seed);

/// SegSLAM sec. 6 merging, "adding the evidence grids": the cells the child observed (in its tiles
/// not shared with `into`) that `into` (the parent's map) has never observed take the
/// child's log-odds. Deviation: the child is a copy-on-write copy of its parent, so its
/// cells already hold the parent's evidence plus its own (adding would count the parent's
/// twice), and overwriting cells the parent knows lets one particle's drift erode a map all
/// particles share (the "evidence erosion" locking is meant to avoid): the parent's
/// evidence is kept, only its coverage grows.
void add_child_evidence(OccupancyGrid& into, const OccupancyGrid& child);

/// Submaps of a map sample pasted into one grid of log-odds (the independence assumption:
/// overlapping evidence adds). A match child pasted after its parent adds only the cells it
/// changed (its tiles not shared with the parent), so copied evidence is not counted twice.
class MapCanvas {
 public:
  /// Sums are clamped to the grid's log-odds bounds [nats], as one grid would clamp them, so
  /// a sample is not more certain than a single map for evidence it merely repeats.
  MapCanvas(double resolution, double log_odds_min, double log_odds_max)
      : resolution_(resolution), min_(log_odds_min), max_(log_odds_max) {}
  void paste(const OccupancyGrid& map, const Pose2& frame, const OccupancyGrid* pasted_parent = nullptr);
  [[nodiscard]] ProbabilityMap to_probability_map() const;

 private:
  double resolution_, min_, max_;
  std::vector<std::pair<CellIndex, double>> cells_;  // target cell, log-odds [nats]
};

}  // namespace lookahead::slam::segslam
