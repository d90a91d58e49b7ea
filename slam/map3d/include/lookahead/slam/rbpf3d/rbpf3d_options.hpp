// SPDX-License-Identifier: MIT
// Every parameter of the 3D RBPF, nested by component. The defaults here are the only copy;
// config/slam3d/default.yaml is checked against them by a test.
#pragma once

#include <cstdint>

#include "lookahead/slam/octree/evidence_octree.hpp"
#include "lookahead/slam/octree/octree_likelihood.hpp"
#include "lookahead/slam/octree/ray_insertion.hpp"

namespace lookahead::slam {

/// Noise of the 4-DoF motion model (x, y, z, yaw); roll and pitch come from the IMU.
struct Motion3Options {
  double xy_per_metre = 0.05;    ///< std of x and y per metre travelled [m/m], >= 0
  double z_per_metre = 0.02;     ///< std of z per metre [m/m], >= 0
  double yaw_per_metre = 0.01;   ///< std of yaw per metre [rad/m], >= 0
  double yaw_per_radian = 0.05;  ///< std of yaw per radian turned [rad/rad], >= 0
  double min_xy = 0.01;          ///< floor of the x, y std per update [m], >= 0
  double min_yaw = 0.002;        ///< floor of the yaw std per update [rad], >= 0
};

struct Rbpf3dOptions {
  int particles = 20;               ///< N, 1..100000
  std::uint64_t seed = 1;           ///< every random draw derives from it
  int threads = 0;                  ///< worker threads for the particle loop; 0 = all cores
  double resample_threshold = 0.5;  ///< resample when N_eff < threshold * N, (0, 1]
  /// Exponent k on the likelihood: w = w p(z|x,m)^k. As in the 2D RBPF, correlated beams
  /// make the raw likelihood overconfident; k < 1 keeps particles alive for a loop closure.
  double weight_exponent = 0.1;
  int likelihood_ray_step = 3;  ///< score every n-th beam that hit, >= 1
  int insert_ray_step = 1;      ///< insert every n-th beam, >= 1
  OctreeOptions map;            ///< 0.2 m voxels by default
  RayInsertOptions insert;      ///< beams inserted up to 15 m
  OctreeLikelihoodOptions likelihood;
  Motion3Options motion;

  /// Throws std::invalid_argument naming the first impossible value.
  void validate() const;
};

}  // namespace lookahead::slam
