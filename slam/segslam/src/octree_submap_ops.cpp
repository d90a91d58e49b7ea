// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/octree_submap_ops.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "lookahead/slam/eval/octree_map_entropy.hpp"
#include "lookahead/slam/parallel/parallel_errors.hpp"
#include "lookahead/slam/segslam/level_coarse_search.hpp"
#include "submap_choice.hpp"

namespace lookahead::slam::segslam {
namespace {

Eigen::Vector3d apply(const Pose4& t, const Eigen::Vector3d& p) {
  const double c = std::cos(t.yaw), s = std::sin(t.yaw);
  return {t.x + c * p.x() - s * p.y(), t.y + s * p.x() + c * p.y(), t.z + p.z()};
}

std::uint64_t pack(const OctreeKey& k) {
  return (static_cast<std::uint64_t>(k.x) << 32) | (static_cast<std::uint64_t>(k.y) << 16) | k.z;
}
OctreeKey unpack(std::uint64_t v) {
  return {static_cast<std::uint16_t>(v >> 32), static_cast<std::uint16_t>(v >> 16), static_cast<std::uint16_t>(v)};
}

// An occupied voxel among the 27 around `p`?
bool explained(OctreeReader& reader, const OctreeGrid& grid, float occupied_above, const Eigen::Vector3d& p) {
  const long kx = grid.axis_key(p.x()), ky = grid.axis_key(p.y()), kz = grid.axis_key(p.z());
  for (long dz = -1; dz <= 1; ++dz) {
    for (long dy = -1; dy <= 1; ++dy) {
      for (long dx = -1; dx <= 1; ++dx) {
        const auto l = reader.log_odds(static_cast<int>(kx + dx), static_cast<int>(ky + dy), static_cast<int>(kz + dz));
        if (l && *l > occupied_above) return true;
      }
    }
  }
  return false;
}

// Why a match fails its acceptance tests, or "" when it passes them.
const char* rejection_of(const Icp3Result& icp, const StructureFit& f, const MatchingOptions& o,
                         const StructureTestOptions& so) {
  if (icp.inlier_ratio < o.min_inlier_ratio) return "icp inliers";
  if (f.points < so.min_points) return "structure points";
  if (f.inlier_ratio < so.min_inlier_ratio) return "structure inliers";
  if (f.free_ratio > so.max_free_ratio) return "free space";
  return "";
}

}  // namespace

// Steps of 1.5 voxels miss no peak, as the near field reaches one voxel around a surface.
LevelPoseGrid coarse_grid(const MatchingOptions& o) {
  return {o.search_radius, 1.5 * o.bin_size, o.search_angle, 0.05};
}

double share_of(int count, const Points3& points) {
  return points.empty() ? 0.0 : static_cast<double>(count) / static_cast<double>(points.size());
}

double predictive_score(const EvidenceOctree& map, const Pose4& pose, const SweepWindow& w) {
  if (w.scored.empty()) return -1.0;
  OctreeReader reader(map);
  const auto above = static_cast<float>(map.options().occupied_above);
  int hits = 0;
  for (const auto& p : w.scored) hits += explained(reader, map.grid(), above, apply(pose, p)) ? 1 : 0;
  return static_cast<double>(hits) / static_cast<double>(w.scored.size());
}

bool has_observed_near(const EvidenceOctree& map, const Eigen::Vector3d& p, double radius) {
  OctreeReader reader(map);
  const OctreeGrid& g = map.grid();
  const double step = std::max(g.resolution(), radius / 4);
  for (double dx = -radius; dx <= radius; dx += step) {
    for (double dy = -radius; dy <= radius; dy += step) {
      for (double dz = -step; dz <= step; dz += step) {
        const Eigen::Vector3d q = p + Eigen::Vector3d(dx, dy, dz);
        if (reader.log_odds(static_cast<int>(g.axis_key(q.x())), static_cast<int>(g.axis_key(q.y())),
                            static_cast<int>(g.axis_key(q.z())))) {
          return true;
        }
      }
    }
  }
  return false;
}

OctreeMatchTarget match_target_of(const EvidenceOctree& map, const MatchingOptions& o) {
  Points3 occupied;
  const auto above = static_cast<float>(map.options().occupied_above);
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    if (l > above) occupied.push_back(map.grid().centre_of(k));
  });
  IcpTarget3 icp(bin_points3(occupied, o.bin_size), o.icp_max_distance);
  IcpTarget3 structure(structure_points(icp).points, o.icp_max_distance);
  return {NearOccupiedField(map, level_bound_widths(coarse_grid(o).step, map.grid().resolution())), std::move(icp),
          std::move(structure)};
}

SweepWindow make_sweep_window(const Points3& points, std::size_t scored_points, const MatchingOptions& o,
                              bool with_structure) {
  SweepWindow w;
  const std::size_t every = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, scored_points));
  for (std::size_t i = 0; i < points.size(); i += every) w.scored.push_back(points[i]);
  w.cloud = bin_points3(points, o.bin_size);
  if (with_structure) find_structure(w, o);
  return w;
}

void find_structure(SweepWindow& w, const MatchingOptions& o) {
  w.structure = structure_points(IcpTarget3(w.cloud, o.icp_max_distance));
}

WindowMatch3 match_window(const OctreeMatchTarget& target, const SweepWindow& w, const Pose4& guess,
                          const MatchingOptions& o, const StructureTestOptions& so) {
  WindowMatch3 m;
  m.rejection = "too few points";
  if (target.icp.size() < 10 || w.cloud.size() < 10) return m;
  const LevelCoarseResult seed = level_search_branch_and_bound(target.field, w.scored, guess, coarse_grid(o));
  m = refine_match(target, w, seed.pose, guess, o, so);
  m.guess_score = share_of(near_in_plane_count(target.field, guess, w.scored), w.scored);
  m.coarse_score = share_of(seed.score, w.scored);
  return m;
}

std::vector<std::vector<LevelCoarseResult>> region_peaks(const OctreeMatchTarget& target, const SweepWindow& w,
                                                         const std::vector<LevelSubgrid>& regions,
                                                         const MatchingOptions& o, std::size_t count, double separation,
                                                         double angle_separation) {
  const LevelSubgrid all = covering_subgrid(regions.front(), regions);
  MatchingOptions grid = o;
  grid.search_radius = all.radius;
  grid.search_angle = all.angle;
  return level_search_peaks_within(target.field, w.scored, all.centre, coarse_grid(grid), regions, count, separation,
                                   angle_separation);
}

RefinedMatches refine_each(const OctreeMatchTarget& target, const SweepWindow& w, const std::vector<Pose4>& seeds,
                           const MatchingOptions& o, const StructureTestOptions& so) {
  RefinedMatches refined;
  ParallelErrors errors;
  for (const Pose4& p : seeds) refined.try_emplace(std::make_tuple(p.x, p.y, p.z, p.yaw));
  for (auto& [key, m] : refined) {
    WindowMatch3* result = &m;
    const Pose4 seed{std::get<0>(key), std::get<1>(key), std::get<2>(key), std::get<3>(key)};
#pragma omp task default(shared) firstprivate(result, seed)
    errors.run([&] { *result = refine_match(target, w, seed, seed, o, so); });
  }
#pragma omp taskwait
  errors.rethrow();
  return refined;
}

std::vector<WindowMatch3> match_regions(const OctreeMatchTarget& target, const SweepWindow& w,
                                        const std::vector<LevelSubgrid>& regions, const MatchingOptions& o,
                                        const StructureTestOptions& so) {
  WindowMatch3 few;
  few.rejection = "too few points";
  std::vector<WindowMatch3> out(regions.size(), few);
  if (regions.empty() || target.icp.size() < 10 || w.cloud.size() < 10) return out;
  // One peak per region: the separations do not matter.
  const std::vector<std::vector<LevelCoarseResult>> peaks = region_peaks(target, w, regions, o, 1, 1.0, 1.0);
  std::vector<LevelCoarseResult> seeds(regions.size());
  std::vector<Pose4> poses;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    // As level_search_branch_and_bound: the guess stands unless a grid pose scores more.
    seeds[r] = {regions[r].centre, near_in_plane_count(target.field, regions[r].centre, w.scored)};
    if (!peaks[r].empty() && peaks[r].front().score > seeds[r].score)
      seeds[r] = {peaks[r].front().pose, peaks[r].front().score};
    seeds[r].pose.z = regions[r].centre.z;
    poses.push_back(seeds[r].pose);
  }
  const RefinedMatches refined = refine_each(target, w, poses, o, so);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const Pose4& s = seeds[r].pose;
    WindowMatch3 m = refined.at(std::make_tuple(s.x, s.y, s.z, s.yaw));
    const LevelSubgrid& region = regions[r];
    m.translation = (m.pose.position() - region.centre.position()).norm();
    m.weight = m.ok ? match_weight(m.icp_error, m.translation, o) : 0.0;
    m.guess_score = share_of(near_in_plane_count(target.field, region.centre, w.scored), w.scored);
    m.coarse_score = share_of(seeds[r].score, w.scored);
    out[r] = m;
  }
  return out;
}

WindowMatch3 refine_match(const OctreeMatchTarget& target, const SweepWindow& w, const Pose4& seed, const Pose4& guess,
                          const MatchingOptions& o, const StructureTestOptions& so) {
  WindowMatch3 m;
  m.rejection = "too few points";
  if (target.icp.size() < 10 || w.cloud.size() < 10) return m;
  return judge_fit(target, w, icp_point_to_plane(w.cloud, target.icp, seed, {o.icp_iterations, o.icp_max_distance}),
                   guess, o, so);
}

WindowMatch3 judge_fit(const OctreeMatchTarget& target, const SweepWindow& w, const Icp3Result& icp, const Pose4& guess,
                       const MatchingOptions& o, const StructureTestOptions& so) {
  WindowMatch3 m;
  m.pose = icp.transform;
  m.all_points_error = icp.mean_error;
  m.translation = (m.pose.position() - guess.position()).norm();
  m.structure = structure_fit(w.structure, target.structure, m.pose,
                              [&](const Eigen::Vector3d& q) { return target.field.seen(q); });
  m.icp_error = m.structure.mean_error;
  m.rejection = rejection_of(icp, m.structure, o, so);
  m.ok = *m.rejection == '\0';
  m.weight = m.ok ? match_weight(m.icp_error, m.translation, o) : 0.0;
  return m;
}

void add_child_evidence(EvidenceOctree& into, const EvidenceOctree& child) {
  if (into.grid().resolution() != child.grid().resolution()) {
    throw std::invalid_argument("add_child_evidence: the child's voxel size differs from its parent's");
  }
  // Collected first: writing `into` while walking it beside the child would change the nodes
  // the walk compares.
  std::vector<std::pair<OctreeKey, float>> fresh;
  child.for_each_voxel_not_shared_with(into, [&](const OctreeKey& k, float l, std::optional<float> parent) {
    if (!parent) fresh.emplace_back(k, l);
  });
  OctreeWriter writer(into);
  for (const auto& [k, l] : fresh) writer.set_log_odds(k, l);
}

void OctreeCanvas::paste(const EvidenceOctree& map, const Pose4& frame, const EvidenceOctree* parent) {
  std::unordered_map<std::uint64_t, std::pair<double, int>> mine;
  std::optional<OctreeReader> parent_reader;
  if (parent) parent_reader.emplace(*parent);
  map.for_each_voxel([&](const OctreeKey& k, float l) {
    double delta = l;
    if (parent_reader) delta -= parent_reader->log_odds(k.x, k.y, k.z).value_or(0.0f);
    if (parent_reader && delta == 0.0) return;  // the parent's evidence, already pasted
    const auto key = grid_.key_of(apply(frame, map.grid().centre_of(k)));
    if (!key) return;
    auto& [sum, n] = mine[pack(*key)];
    sum += delta;
    ++n;
  });
  // Rotated voxels alias: the average of a submap's voxels landing in one target voxel.
  for (const auto& [k, sn] : mine) cells_[k] += sn.first / sn.second;
}

EvidenceOctree OctreeCanvas::to_octree() const {
  EvidenceOctree out(options_);
  OctreeWriter writer(out);
  for (const auto& [k, l] : cells_) {
    writer.set_log_odds(unpack(k), static_cast<float>(std::clamp(l, options_.log_odds_min, options_.log_odds_max)));
  }
  return out;
}

double OctreeCanvas::entropy() const {
  double h = 0;
  for (const auto& [k, l] : cells_) h += voxel_entropy(std::clamp(l, options_.log_odds_min, options_.log_odds_max));
  return h * std::pow(options_.resolution, 3);
}

}  // namespace lookahead::slam::segslam
