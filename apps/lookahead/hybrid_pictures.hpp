// SPDX-License-Identifier: MIT
// Pictures of HybridSLAM runs: a feature map with its 3-sigma covariance ellipses and
// trajectories over a grid (an occupancy map for real logs, a blank world in simulation).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "lookahead/slam/hybrid/submap_filter.hpp"
#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::app {

/// The boundary of the `sigmas` ellipse of a 2D Gaussian as points (drawn as dots).
std::vector<std::pair<double, double>> ellipse_points(const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov,
                                                      double sigmas = 3.0, int n = 36);

/// Point sets for a feature map: the means (large) and their 3-sigma ellipses (small dots).
std::vector<slam::PicturePoints> feature_layers(const std::vector<slam::hybrid::MapFeature>& map,
                                                const std::string& label, slam::Rgb colour);

/// A blank (all free) map covering [x0, x1] x [y0, y1], to draw simulated worlds on.
slam::ProbabilityMap blank_map(double x0, double y0, double x1, double y1, double resolution);

}  // namespace lookahead::app
