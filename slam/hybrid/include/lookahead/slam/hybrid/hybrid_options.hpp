// SPDX-License-Identifier: MIT
// Parameters of HybridSLAM (Brooks & Bailey, "HybridSLAM: Combining FastSLAM and EKF-SLAM
// for reliable mapping"): the FastSLAM 2.0 front-end, feature existence (HybridSLAM eq. (11)), sub-map
// fusion (HybridSLAM sec. 4) and the range-bearing sensor. Defaults are HybridSLAM sec. 5 values;
// config/hybrid/default.yaml mirrors them (`lookahead config dump hybrid`).
#pragma once

#include <cstdint>

namespace lookahead::slam::hybrid {

/// Range-bearing sensor (HybridSLAM sec. 5.2: 360 deg, 25 m, 0.05 m and 1 deg noise).
struct SensorOptions {
  double max_range = 25.0;                      ///< [m], > 0
  double sigma_range = 0.05;                    ///< [m], > 0
  double sigma_bearing = 0.017453292519943295;  ///< [rad] (1 deg), > 0
};

/// Probability of existence of a feature, updated per HybridSLAM sec. 5.1 HybridSLAM eq. (11).
struct ExistenceOptions {
  double alpha = 1.0;            ///< p(detect | feature in view), (0, 1]
  double beta = 0.0;             ///< p(false alarm | feature in view), [0, 1)
  double prior = 0.5;            ///< existence before the observation that creates a feature
  double fuse_threshold = 0.95;  ///< only features above this are fused (HybridSLAM sec. 5.1)
  double cull_threshold = 0.02;  ///< features below this are deleted
  /// Features predicted this far inside the sensor range count as "in view" for the
  /// missed-detection update [m]: a feature at the edge may truly be out of range.
  double view_margin = 1.0;
  /// Deviation: the filters clamp alpha and beta into [floor, 1 - floor]. With the paper's
  /// alpha = 1 one missed detection (a feature near the range limit) would set p = 0, and
  /// with beta = 0 a single observation would make any feature certain.
  double clamp = 0.02;
};

/// FastSLAM 2.0 with data association sampling (Montemerlo et al. 2003; HybridSLAM sec. 3, 5.1).
struct FastSlamOptions {
  int particles = 500;              ///< P, >= 1 (HybridSLAM sec. 5.1)
  double resample_threshold = 0.5;  ///< resample when N_eff < this * P
  /// Likelihood of "a new feature" for an observation no mapped feature explains, in the
  /// units of the range-bearing density [1/(m rad)] (Montemerlo's p0).
  double new_feature_likelihood = 1e-5;
  /// Candidates are features within this distance of the observed point [m] (a cheap
  /// pre-gate; the chi-square gate below decides).
  double candidate_radius = 6.0;
  double gate_chi2 = 13.8;  ///< individual gate on the innovation (2 dof, 99.9 %)
  std::uint64_t seed = 1;   ///< seed of every random draw of the filter
};

/// Sub-map fusion into the EKF global map (HybridSLAM sec. 4).
struct FusionOptions {
  double period = 10.0;           ///< T: local map age at fusion [s] (HybridSLAM sec. 5.1)
  double jcbb_confidence = 0.99;  ///< joint compatibility test level
  /// Std added to each pair's difference in the association test only [m] (see global_map.cpp).
  double association_sigma = 0.15;
  int jcbb_max_nodes = 20000;  ///< cap on the branch-and-bound search
  /// Beyond the paper: after each fusion, re-solve the global map over all local maps by
  /// Gauss-Newton (every Jacobian at the current solution) instead of keeping the EKF's
  /// once-linearised result (see global_map.cpp). Off: the paper's one-step EKF.
  bool relinearise = true;
  int relinearise_iterations = 10;  ///< Gauss-Newton steps per fusion, at most
};

/// Process noise every filter assumes at least, on top of the control's own model.
/// Deviation: the paper's velocity noise (0.25 v, 0.35 omega) has no heading noise on a
/// straight line, so after a turn FastSLAM's particles keep one heading forever and
/// resampling collapses them onto it (without a floor every FastSLAM-based filter failed
/// within seconds). A small floor keeps the heading and lateral position explorable by
/// the FastSLAM 2.0 proposal. It is given to every filter, so the comparison stays fair.
struct ProcessNoiseFloor {
  double xy = 0.02;     ///< [m / sqrt(s)] on each position component of the increment
  double theta = 0.01;  ///< [rad / sqrt(s)]
};

struct HybridOptions {
  ProcessNoiseFloor process_floor;
  SensorOptions sensor;
  ExistenceOptions existence;
  FastSlamOptions fastslam;
  FusionOptions fusion;
};

}  // namespace lookahead::slam::hybrid
