// SPDX-License-Identifier: MIT
// The map-type-specific operations of SegSLAM (Fairfield et al. 2010, SegSLAM sec. 4.3-4.5, 5.4) for
// the copy-on-write evidence octree and level poses (x, y, z, yaw): the 3D counterpart of
// grid_submap_ops.hpp. The graph code (SegMap, map samples, trajectory reconstruction, the
// SegSLAM eq. (3)/(18) choice, segmentation) is the same generic code the 2D filter uses.
//   insert / score a sweep   the rbpf3d particle step (ray_insertion, octree_likelihood)
//   predictive_score         SegSLAM eq. (17) on the look-ahead window
//   has_observed_near        spatial-proximity winnowing (SegSLAM sec. 4.5.1)
//   match_window             coarse search + point-to-plane ICP on binned points, SegSLAM eq. (18)
//   add_child_evidence       merging a re-entered submap into its parent (SegSLAM sec. 6)
//   OctreeCanvas             a map sample's submaps in one octree, SegSLAM eq. (22) entropy
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "lookahead/slam/geometry/pose4.hpp"
#include "lookahead/slam/octree/evidence_octree.hpp"
#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "lookahead/slam/segslam/near_occupied_field.hpp"
#include "lookahead/slam/segslam/point_icp3.hpp"
#include "lookahead/slam/segslam/segslam_options.hpp"
#include "lookahead/slam/segslam/structure_fit.hpp"

namespace lookahead::slam::segslam {

/// A look-ahead window's end points in the level frame of the robot at its first sweep
/// (dead-reckoned; position and yaw of that sweep, no roll or pitch).
struct SweepWindow {
  Points3 scored;             ///< a thinned sample for SegSLAM eq. (17) and the coarse search
  Points3 cloud;              ///< every end point, binned, for ICP
  OrientedPoints3 structure;  ///< the cloud's walls, columns and cars (structure_fit.hpp)
};

/// A window of end points (level frame of the robot at its first sweep): `scored` thinned to
/// about `scored_points`, the cloud binned, and (`with_structure`) its structure points found.
SweepWindow make_sweep_window(const Points3& points, std::size_t scored_points, const MatchingOptions& options,
                              bool with_structure = true);
/// Finds the window's structure points (normals by PCA: the costly part, left for matching).
void find_structure(SweepWindow& window, const MatchingOptions& options);

/// SegSLAM eq. (17): the share of the window's scored points that `map` explains (an occupied voxel
/// among the 27 around the point) with the robot at `pose` at the window's start; -1 when
/// the window is empty.
double predictive_score(const EvidenceOctree& map, const Pose4& pose, const SweepWindow& window);

/// SegSLAM sec. 4.5.1 spatial proximity: does `map` hold observed voxels within `radius` of `p`?
bool has_observed_near(const EvidenceOctree& map, const Eigen::Vector3d& p, double radius);

/// The coarse search's grid for `options`: steps of 1.5 bins miss no peak, as the near field
/// reaches one voxel around a surface; yaw in steps of 0.05 rad.
LevelPoseGrid coarse_grid(const MatchingOptions& options);
/// The share of `points` a count of them is (0 for none).
double share_of(int count, const Points3& points);

/// What matching needs of a closed submap, built once per candidate and shared by every
/// particle and attempt (a closed submap never changes).
struct OctreeMatchTarget {
  NearOccupiedField field;  ///< with the coarse search's bound levels
  IcpTarget3 icp;           ///< occupied voxel centres, binned
  IcpTarget3 structure;     ///< those of them whose surface is structure, normals of their own
};
OctreeMatchTarget match_target_of(const EvidenceOctree& map, const MatchingOptions& options);

struct WindowMatch3 {
  bool ok = false;
  Pose4 pose;                     ///< the robot at the window's start, in the candidate's frame
  double icp_error = 0.0;         ///< SegSLAM eq. (18) err_ICP: the structure points' mean error [m]
  double all_points_error = 0.0;  ///< ICP's mean error over all points, floor and ceiling too [m]
  double translation = 0.0;       ///< tau_m: distance from the guess [m]
  double weight = 0.0;            ///< SegSLAM eq. (18)
  StructureFit structure;         ///< the window's structure at `pose`
  double guess_score = 0.0;       ///< the coarse search's score (share of points near surfaces) at the guess
  double coarse_score = 0.0;      ///< ... and at its best pose, which seeds ICP
  const char* rejection = "";     ///< why the match failed (empty when ok): for the debug log
  /// Wide re-entry search only (wide_reentry.hpp): distinct poses that passed the tests.
  std::size_t modes = 0;
  /// SegSLAM eq. (19)'s p(|Sigma_X|) when the localisation filter matched (localization_match3.hpp);
  /// 1 for ICP. The match's weight is this times SegSLAM eq. (18)'s.
  double spread_factor = 1.0;
};

/// SegSLAM sec. 4.5: a coarse search (x, y, yaw around `guess`, share of points near occupied voxels)
/// seeds point-to-plane ICP of the binned window onto the candidate; weighted by SegSLAM eq. (18).
/// Deviation: SegSLAM eq. (18)'s err_ICP is the mean error of the window's structure points (walls,
/// columns, cars; structure_fit.hpp), not of all points, and a match needs enough of them
/// fitted (`structure`): floor and ceiling fit a wrong re-entry as well as the right one.
WindowMatch3 match_window(const OctreeMatchTarget& target, const SweepWindow& window, const Pose4& guess,
                          const MatchingOptions& options, const StructureTestOptions& structure = {});
/// Searching several regions of one candidate together (match_regions, and the wide stage's
/// match_regions_unambiguous): up to `count` distinct coarse peaks of each region's own part
/// of the grid covering them all (level_search_peaks_within on covering_subgrid(regions)).
std::vector<std::vector<LevelCoarseResult>> region_peaks(const OctreeMatchTarget& target, const SweepWindow& window,
                                                         const std::vector<LevelSubgrid>& regions,
                                                         const MatchingOptions& options, std::size_t count,
                                                         double separation, double angle_separation);
/// refine_match from each distinct seed pose once, as OpenMP tasks (inside SegSlam3d's update
/// the other thread, done with its particles, takes some), keyed by the seed's (x, y, z, yaw);
/// tau and the weight are taken against the seed.
using RefinedMatches = std::map<std::tuple<double, double, double, double>, WindowMatch3>;
RefinedMatches refine_each(const OctreeMatchTarget& target, const SweepWindow& window, const std::vector<Pose4>& seeds,
                           const MatchingOptions& options, const StructureTestOptions& structure);

/// match_window for several guesses on one candidate, searched together: each region (centre
/// = a guess, radius and angle = its search's reach) gets the best pose of its own part of
/// the grid of the square covering them all (the regions share the block scores and bounds:
/// level_search_peaks_within), its centre unless a grid pose scores more, as match_window;
/// each distinct pose is refined by ICP once (as OpenMP tasks). With centres on one lattice
/// of the coarse steps every region sees the grid poses it would see alone. tau and the
/// weight are taken from the region's centre.
std::vector<WindowMatch3> match_regions(const OctreeMatchTarget& target, const SweepWindow& window,
                                        const std::vector<LevelSubgrid>& regions, const MatchingOptions& options,
                                        const StructureTestOptions& structure = {});
/// match_window's ICP from `seed` and its acceptance tests, without the coarse search (its
/// scores are left 0); tau and the SegSLAM eq. (18) weight are taken against `guess`.
WindowMatch3 refine_match(const OctreeMatchTarget& target, const SweepWindow& window, const Pose4& seed,
                          const Pose4& guess, const MatchingOptions& options,
                          const StructureTestOptions& structure = {});
/// The acceptance tests and SegSLAM eq. (18) weight of the window placed by `fit` (ICP's result, or a
/// pose found otherwise with point_to_plane_fit's statistics): refine_match after its ICP.
WindowMatch3 judge_fit(const OctreeMatchTarget& target, const SweepWindow& window, const Icp3Result& fit,
                       const Pose4& guess, const MatchingOptions& options, const StructureTestOptions& structure = {});

/// SegSLAM sec. 6 merging, as the 2D add_child_evidence: adds to `into` (the parent) the voxels of
/// `child` (a match copy of it, same frame) that `into` never observed, with the child's
/// log-odds; voxels the parent observed keep the parent's evidence (the child's revisions of
/// them are dropped: its copy started from them, so adding would count them twice). Bricks
/// the child still shares with the parent are not visited. Throws std::invalid_argument when
/// the voxel sizes differ.
void add_child_evidence(EvidenceOctree& into, const EvidenceOctree& child);

/// Submaps of a map sample summed into one set of voxels (independence: overlapping evidence
/// adds, clamped to the map's bounds); a match child pasted with its parent (before or after
/// it: the sum does not depend on the order) adds only what it changed, so copied evidence is
/// not counted twice.
class OctreeCanvas {
 public:
  explicit OctreeCanvas(const OctreeOptions& options) : options_(options), grid_(options.resolution) {}
  void paste(const EvidenceOctree& map, const Pose4& frame, const EvidenceOctree* pasted_parent = nullptr);
  [[nodiscard]] EvidenceOctree to_octree() const;
  /// SegSLAM eq. (22) with gamma = the voxel volume [nats m^3], over every observed voxel.
  [[nodiscard]] double entropy() const;
  [[nodiscard]] std::size_t voxels() const { return cells_.size(); }

 private:
  OctreeOptions options_;
  OctreeGrid grid_;
  std::unordered_map<std::uint64_t, double> cells_;  // packed key -> summed log-odds [nats]
};

}  // namespace lookahead::slam::segslam
