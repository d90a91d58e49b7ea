// SPDX-License-Identifier: MIT
#include "lookahead/predictor/map_features.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace lookahead::predictor {

double LineSegment::length() const { return std::hypot(x1 - x0, y1 - y0); }
double LineSegment::angle() const { return std::atan2(y1 - y0, x1 - x0); }

namespace {

struct Raster {
  cv::Mat occupied;  // 255 on wall cells; row 0 = lowest y
  slam::CellIndex lo;
  double res = 0.05;
  [[nodiscard]] double x(double col) const { return (lo.x + col + 0.5) * res; }
  [[nodiscard]] double y(double row) const { return (lo.y + row + 0.5) * res; }
};

Raster rasterize(const slam::OccupancyGrid& grid, double threshold, slam::CellIndex lo, slam::CellIndex hi) {
  Raster r;
  r.res = grid.resolution();
  if (lo.x > hi.x && !grid.known_bounds(lo, hi)) return r;
  r.lo = lo;
  r.occupied = cv::Mat::zeros(hi.y - lo.y + 1, hi.x - lo.x + 1, CV_8UC1);
  for (int row = 0; row < r.occupied.rows; ++row) {
    for (int col = 0; col < r.occupied.cols; ++col) {
      const slam::CellIndex c{lo.x + col, lo.y + row};
      if (grid.is_known(c) && grid.probability(c) >= threshold) r.occupied.at<std::uint8_t>(row, col) = 255;
    }
  }
  return r;
}

std::vector<LineSegment> hough_lines(const Raster& r, const FeatureOptions& o) {
  std::vector<cv::Vec4i> found;
  // Probabilistic Hough transform: 1-cell distance and 1-degree angle resolution.
  cv::HoughLinesP(r.occupied, found, 1.0, M_PI / 180.0, o.hough_votes, o.min_line_length / r.res,
                  o.max_line_gap / r.res);
  std::vector<LineSegment> lines;
  for (const cv::Vec4i& l : found) lines.push_back({r.x(l[0]), r.y(l[1]), r.x(l[2]), r.y(l[3])});
  return lines;
}

// The direction from (x, y) along the segment, towards its end farther from the point.
double away_from(const LineSegment& l, double x, double y) {
  const bool far_is_1 = std::hypot(l.x1 - x, l.y1 - y) >= std::hypot(l.x0 - x, l.y0 - y);
  return far_is_1 ? std::atan2(l.y1 - y, l.x1 - x) : std::atan2(l.y0 - y, l.x0 - x);
}

double distance_to_segment(const LineSegment& l, double x, double y) {
  const double dx = l.x1 - l.x0, dy = l.y1 - l.y0;
  const double len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((x - l.x0) * dx + (y - l.y0) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(l.x0 + t * dx - x, l.y0 + t * dy - y);
}

bool meet_at_corner(const LineSegment& a, const LineSegment& b, const FeatureOptions& o, Corner& c) {
  const double turn = std::abs(std::remainder(a.angle() - b.angle(), M_PI));  // in [0, pi/2]
  if (turn < o.min_corner_angle) return false;
  const double ax = a.x1 - a.x0, ay = a.y1 - a.y0, bx = b.x1 - b.x0, by = b.y1 - b.y0;
  const double den = ax * by - ay * bx;
  if (std::abs(den) < 1e-12) return false;
  const double t = ((b.x0 - a.x0) * by - (b.y0 - a.y0) * bx) / den;
  c.x = a.x0 + t * ax;
  c.y = a.y0 + t * ay;
  if (distance_to_segment(a, c.x, c.y) > o.corner_reach || distance_to_segment(b, c.x, c.y) > o.corner_reach)
    return false;
  c.angle_a = away_from(a, c.x, c.y);
  c.angle_b = away_from(b, c.x, c.y);
  c.source = Corner::Source::kLineIntersection;
  return true;
}

bool near_existing(const std::vector<Corner>& corners, double x, double y, double separation) {
  return std::any_of(corners.begin(), corners.end(),
                     [&](const Corner& c) { return std::hypot(c.x - x, c.y - y) < separation; });
}

// Shi-Tomasi corners of the wall image that no line intersection explains (a wall end, a
// rounded or cluttered corner); each takes the two lines passing nearest to it.
void gradient_corners(const Raster& r, const std::vector<LineSegment>& lines, const FeatureOptions& o,
                      std::vector<Corner>& corners) {
  std::vector<cv::Point2f> pts;
  cv::goodFeaturesToTrack(r.occupied, pts, o.max_gradient_corners, o.gradient_quality, o.min_corner_separation / r.res);
  for (const cv::Point2f& p : pts) {
    const double x = r.x(p.x), y = r.y(p.y);
    if (near_existing(corners, x, y, o.min_corner_separation)) continue;
    const LineSegment* first = nullptr;
    const LineSegment* second = nullptr;
    for (const LineSegment& l : lines) {
      if (distance_to_segment(l, x, y) > o.corner_reach) continue;
      if (!first)
        first = &l;
      else if (!second && std::abs(std::remainder(first->angle() - l.angle(), M_PI)) >= o.min_corner_angle)
        second = &l;
    }
    if (!first || !second) continue;  // P-SLAM registers corners by their two lines
    corners.push_back({x, y, away_from(*first, x, y), away_from(*second, x, y), Corner::Source::kGradient});
  }
}

}  // namespace

MapFeatures extract_features(const slam::OccupancyGrid& grid, const FeatureOptions& o, slam::CellIndex lo,
                             slam::CellIndex hi) {
  if (!(o.occupied_threshold > 0.5 && o.occupied_threshold < 1) || o.hough_votes < 2 || o.min_line_length <= 0 ||
      o.max_line_gap < 0 || o.corner_reach <= 0 || o.max_gradient_corners < 0 ||
      !(o.gradient_quality > 0 && o.gradient_quality < 1) || o.min_corner_separation <= 0) {
    throw std::invalid_argument("feature options out of range");
  }
  MapFeatures f;
  const Raster r = rasterize(grid, o.occupied_threshold, lo, hi);
  if (r.occupied.empty()) return f;
  f.lines = hough_lines(r, o);
  for (std::size_t i = 0; i < f.lines.size(); ++i) {
    for (std::size_t j = i + 1; j < f.lines.size(); ++j) {
      Corner c;
      if (meet_at_corner(f.lines[i], f.lines[j], o, c) &&
          !near_existing(f.corners, c.x, c.y, o.min_corner_separation)) {
        f.corners.push_back(c);
      }
    }
  }
  if (o.max_gradient_corners > 0) gradient_corners(r, f.lines, o, f.corners);
  return f;
}

}  // namespace lookahead::predictor
