// SPDX-License-Identifier: MIT
#include "lookahead/slam/hybrid/scan_landmarks.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lookahead::slam::hybrid {
namespace {

struct Beam {
  std::size_t index;
  double range;
  Eigen::Vector2d point;  // robot frame
};

struct Segment {
  std::size_t first, last;            // into the run
  Eigen::Vector2d centre, direction;  // total-least-squares line
  Eigen::Vector2d a, b;               // end points projected on the line
};

double distance_to_chord(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double n = d.norm();
  if (n < 1e-9) return (p - a).norm();
  return std::abs(d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x())) / n;
}

Eigen::Vector2d point_of(const LaserScan& scan, std::size_t beam) {
  const double r = scan.ranges[beam];
  const Pose2 p = scan.laser_offset.compose({r * std::cos(scan.bearing(beam)), r * std::sin(scan.bearing(beam)), 0.0});
  return {p.x, p.y};
}

// Runs of consecutive returns without a jump.
std::vector<std::vector<Beam>> runs_of(const LaserScan& scan, const ScanLandmarkOptions& o) {
  std::vector<std::vector<Beam>> runs(1);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!scan.is_return(i) || r > o.max_range) {
      if (!runs.back().empty()) runs.emplace_back();
      continue;
    }
    const Beam beam{i, r, point_of(scan, i)};
    auto& run = runs.back();
    const double limit = o.break_distance + 3.0 * r * std::abs(scan.angle_increment);
    if (!run.empty() && (beam.index != run.back().index + 1 || (beam.point - run.back().point).norm() > limit)) {
      runs.emplace_back();
    }
    runs.back().push_back(beam);
  }
  return runs;
}

void split(const std::vector<Beam>& run, std::size_t first, std::size_t last, const ScanLandmarkOptions& o,
           std::vector<std::pair<std::size_t, std::size_t>>& out) {
  double worst = 0.0;
  std::size_t at = first;
  for (std::size_t i = first + 1; i < last; ++i) {
    const double d = distance_to_chord(run[i].point, run[first].point, run[last].point);
    if (d > worst) worst = d, at = i;
  }
  if (worst > o.split_tolerance && at > first && at < last) {
    split(run, first, at, o, out);
    split(run, at, last, o, out);
  } else {
    out.emplace_back(first, last);
  }
}

Segment fit(const std::vector<Beam>& run, std::size_t first, std::size_t last) {
  Segment s{first, last, Eigen::Vector2d::Zero(), {}, {}, {}};
  const double n = static_cast<double>(last - first + 1);
  for (std::size_t i = first; i <= last; ++i) s.centre += run[i].point / n;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (std::size_t i = first; i <= last; ++i)
    scatter += (run[i].point - s.centre) * (run[i].point - s.centre).transpose();
  s.direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
  const auto project = [&](const Eigen::Vector2d& p) { return s.centre + s.direction * s.direction.dot(p - s.centre); };
  s.a = project(run[first].point);
  s.b = project(run[last].point);
  return s;
}

bool intersect(const Segment& s, const Segment& t, Eigen::Vector2d& at) {
  Eigen::Matrix2d m;
  m << s.direction, -t.direction;
  if (std::abs(m.determinant()) < 1e-6) return false;
  const Eigen::Vector2d k = m.lu().solve(t.centre - s.centre);
  at = s.centre + k.x() * s.direction;
  return true;
}

// The end of a run is free (a true line end) when the beam beyond it returns far behind or
// not at all; a nearer neighbour occludes it. A farther return that lies on the segment's
// own line is the same wall continuing (cut by max_range, or seen at grazing incidence
// where the beam spacing exceeds the break distance): no end there.
bool end_is_free(const LaserScan& scan, const Beam& end, const Segment& s, long step, const ScanLandmarkOptions& o) {
  const long j = static_cast<long>(end.index) + step;
  if (j < 0 || j >= static_cast<long>(scan.ranges.size())) return false;  // edge of the field of view
  const std::size_t k = static_cast<std::size_t>(j);
  if (!scan.is_return(k)) return true;
  if (scan.ranges[k] <= end.range + o.occlusion_margin) return false;
  const Eigen::Vector2d n(-s.direction.y(), s.direction.x());
  return std::abs(n.dot(point_of(scan, k) - s.centre)) > o.continuation_distance;
}

// The beam meets the segment's line at least min_incidence steeply at the end: at grazing
// incidence the last return is set by the beam spacing and moves with the robot.
bool end_is_steep(const Beam& end, const Segment& s, const LaserScan& scan, const ScanLandmarkOptions& o) {
  const Eigen::Vector2d origin(scan.laser_offset.x, scan.laser_offset.y);
  const Eigen::Vector2d beam = (end.point - origin).normalized();
  return std::abs(beam.x() * s.direction.y() - beam.y() * s.direction.x()) >= std::sin(o.min_incidence);
}

ScanLandmark line_end(const Eigen::Vector2d& p, const Segment& s, double range, const LaserScan& scan,
                      const ScanLandmarkOptions& o) {
  const double along = o.end_sigma_along + range * std::abs(scan.angle_increment);
  const Eigen::Vector2d n(-s.direction.y(), s.direction.x());
  const Eigen::Matrix2d cov = along * along * s.direction * s.direction.transpose() +
                              o.end_sigma_across * o.end_sigma_across * n * n.transpose();
  return {ScanLandmark::Kind::kLineEnd, p, cov};
}

}  // namespace

std::vector<ScanLandmark> extract_scan_landmarks(const LaserScan& scan, const ScanLandmarkOptions& o) {
  std::vector<ScanLandmark> out;
  for (const auto& run : runs_of(scan, o)) {
    if (run.size() < static_cast<std::size_t>(o.min_points)) continue;
    std::vector<std::pair<std::size_t, std::size_t>> pieces;
    split(run, 0, run.size() - 1, o, pieces);
    std::vector<Segment> segs;
    for (const auto& [a, b] : pieces) {
      if (b - a + 1 < static_cast<std::size_t>(o.min_points)) continue;
      Segment s = fit(run, a, b);
      if ((s.b - s.a).norm() >= o.min_length) segs.push_back(s);
    }
    for (std::size_t i = 0; i + 1 < segs.size(); ++i) {
      const Segment &s = segs[i], &t = segs[i + 1];
      if (t.first != s.last) continue;  // not neighbours on the run
      const double angle = std::acos(std::min(1.0, std::abs(s.direction.dot(t.direction))));
      Eigen::Vector2d c;
      if (angle < o.corner_min_angle || !intersect(s, t, c) || (c - run[s.last].point).norm() > o.corner_max_gap)
        continue;
      out.push_back({ScanLandmark::Kind::kCorner, c, o.corner_sigma * o.corner_sigma * Eigen::Matrix2d::Identity()});
    }
    if (!o.line_ends || segs.empty()) continue;
    const Segment &head = segs.front(), &tail = segs.back();
    if (head.first == 0 && end_is_free(scan, run.front(), head, -1, o) && end_is_steep(run.front(), head, scan, o)) {
      out.push_back(line_end(head.a, head, run.front().range, scan, o));
    }
    if (tail.last == run.size() - 1 && end_is_free(scan, run.back(), tail, +1, o) &&
        end_is_steep(run.back(), tail, scan, o)) {
      out.push_back(line_end(tail.b, tail, run.back().range, scan, o));
    }
  }
  return out;
}

void validate(const ScanLandmarkOptions& o) {
  const auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("scan_landmarks.") + what);
  };
  require(o.max_range > 0.0, "max_range must be > 0");
  require(o.break_distance > 0.0, "break_distance must be > 0");
  require(o.split_tolerance > 0.0, "split_tolerance must be > 0");
  require(o.min_points >= 2, "min_points must be >= 2");
  require(o.min_length >= 0.0, "min_length must be >= 0");
  require(o.corner_min_angle > 0.0 && o.corner_min_angle <= M_PI / 2, "corner_min_angle must be in (0, pi/2]");
  require(o.corner_max_gap > 0.0, "corner_max_gap must be > 0");
  require(o.occlusion_margin >= 0.0, "occlusion_margin must be >= 0");
  require(o.continuation_distance >= 0.0, "continuation_distance must be >= 0");
  require(o.min_incidence >= 0.0 && o.min_incidence < M_PI / 2, "min_incidence must be in [0, pi/2)");
  require(o.corner_sigma > 0.0 && o.end_sigma_across > 0.0 && o.end_sigma_along > 0.0, "sigmas must be > 0");
}

RangeBearing to_observation(const ScanLandmark& l) {
  const double x = l.point.x(), y = l.point.y();
  const double q = std::max(x * x + y * y, 1e-12), r = std::sqrt(q);
  Eigen::Matrix2d j;
  j << x / r, y / r, -y / q, x / q;
  return {r, std::atan2(y, x), j * l.covariance * j.transpose()};
}

}  // namespace lookahead::slam::hybrid
