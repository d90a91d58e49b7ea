// SPDX-License-Identifier: MIT
#include "hybrid_pictures.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace lookahead::app {

std::vector<std::pair<double, double>> ellipse_points(const Eigen::Vector2d& mean, const Eigen::Matrix2d& cov,
                                                      double sigmas, int n) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(cov);
  const Eigen::Vector2d radii = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt() * sigmas;
  std::vector<std::pair<double, double>> out;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    const Eigen::Vector2d p =
        mean + eig.eigenvectors() * Eigen::Vector2d(radii.x() * std::cos(a), radii.y() * std::sin(a));
    out.emplace_back(p.x(), p.y());
  }
  return out;
}

std::vector<slam::PicturePoints> feature_layers(const std::vector<slam::hybrid::MapFeature>& map,
                                                const std::string& label, slam::Rgb colour) {
  slam::PicturePoints means{{}, colour, label, 4};
  slam::PicturePoints ellipses{{}, colour, "3-sigma ellipses", 1};
  for (const auto& f : map) {
    means.points.emplace_back(f.mean.x(), f.mean.y());
    for (const auto& p : ellipse_points(f.mean, f.covariance)) ellipses.points.push_back(p);
  }
  return {ellipses, means};
}

slam::ProbabilityMap blank_map(double x0, double y0, double x1, double y1, double resolution) {
  slam::ProbabilityMap m;
  m.resolution = resolution;
  m.origin_x = x0;
  m.origin_y = y0;
  m.width = static_cast<int>(std::ceil((x1 - x0) / resolution));
  m.height = static_cast<int>(std::ceil((y1 - y0) / resolution));
  m.p.assign(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height), 0.0);
  return m;
}

}  // namespace lookahead::app
