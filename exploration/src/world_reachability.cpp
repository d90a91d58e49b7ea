// SPDX-License-Identifier: MIT
#include "lookahead/exploration/world_reachability.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <stdexcept>

#include "lookahead/exploration/robot.hpp"

namespace lookahead::exploration {
namespace {

// [m] largest spacing of the flood's samples. The robot collides as a disc against wall
// squares (`disc_collides`); on plans drawn at 0.2 m per pixel a flood over pixel centres
// has to round a door of 2 pixels to open or shut for a 0.2 m robot. At 5 cm the rounding
// costs at most a centimetre of clearance.
constexpr double kSampleStep = 0.05;

// Samples per world cell along each axis, and their spacing.
struct Sampling {
  int per_cell = 1;
  double step = 0.0;
};

Sampling sampling_of(const World& w) {
  Sampling s;
  s.per_cell = std::max(1, static_cast<int>(std::ceil(w.resolution() / kSampleStep - 1e-9)));
  s.step = w.resolution() / s.per_cell;
  return s;
}

// 255 on samples whose world cell is free, with a frame one cell wide that counts as wall
// (outside the plan is occupied). Sample (u, v) of the frame-less grid sits at the centre of
// the u-th sub-square of its cell row.
cv::Mat free_samples(const World& w, const Sampling& s) {
  const int f = s.per_cell;
  cv::Mat free((w.height() + 2) * f, (w.width() + 2) * f, CV_8U, cv::Scalar(0));
  for (int y = 0; y < w.height(); ++y) {
    for (int x = 0; x < w.width(); ++x) {
      if (w.is_occupied(slam::CellIndex{x, y})) continue;
      free(cv::Rect((x + 1) * f, (y + 1) * f, f, f)).setTo(255);
    }
  }
  return free;
}

// 255 where the robot's centre fits: the distance from the sample to the nearest wall square
// is at least the radius. distanceTransform measures to the nearest wall sample's centre, half
// a sample beyond the square's face.
cv::Mat centre_space(const cv::Mat& free, const Sampling& s, double radius) {
  if (radius <= 0) return free.clone();
  cv::Mat dist;
  cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  cv::Mat fits;
  cv::compare(dist, static_cast<float>(radius / s.step + 0.5), fits, cv::CMP_GE);
  return fits;
}

// 4-connected (no diagonal squeeze between two corners) flood of `space` from `start`; the
// frame's samples are 0, so the fill never leaves the grid. Marks the reached samples 255.
cv::Mat flood(const cv::Mat& space, cv::Point start) {
  constexpr int kReached = 128;
  cv::Mat fill = space.clone();
  cv::floodFill(fill, start, kReached, nullptr, 0, 0, 4);
  cv::Mat reached;
  cv::compare(fill, kReached, reached, cv::CMP_EQ);
  return reached;
}

// Row-major world-cell mask: 1 where any sample of the cell is set in `samples`.
std::vector<std::uint8_t> cells_touched(const cv::Mat& samples, const World& w, int f) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(w.width()) * w.height(), 0);
  for (int y = 0; y < w.height(); ++y) {
    for (int x = 0; x < w.width(); ++x) {
      if (cv::countNonZero(samples(cv::Rect((x + 1) * f, (y + 1) * f, f, f))) > 0) {
        out[static_cast<std::size_t>(y) * w.width() + x] = 1;
      }
    }
  }
  return out;
}

// The fitting sample the flood starts from: the one holding `start`, else the nearest of its
// eight neighbours that fits (a start the robot's check allows can lie up to a centimetre
// closer to a corner than the samples' rounding grants).
std::optional<cv::Point> seed_sample(const cv::Mat& space, const World& w, const Sampling& s,
                                     const Eigen::Vector2d& start) {
  const Eigen::Vector2d local = (start - w.origin()) / s.step;
  const cv::Point home(static_cast<int>(std::floor(local.x())) + s.per_cell,
                       static_cast<int>(std::floor(local.y())) + s.per_cell);
  std::optional<cv::Point> best;
  double best_d2 = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const cv::Point c(home.x + dx, home.y + dy);
      if (space.at<std::uint8_t>(c) == 0) continue;
      const double ex = c.x - s.per_cell + 0.5 - local.x(), ey = c.y - s.per_cell + 0.5 - local.y();
      if (!best || ex * ex + ey * ey < best_d2) {
        best = c;
        best_d2 = ex * ex + ey * ey;
      }
    }
  }
  return best;
}

}  // namespace

ReachableArea reachable_free_area(const World& world, const Eigen::Vector2d& start, double robot_radius) {
  if (!(robot_radius >= 0)) throw std::invalid_argument("robot_radius must be >= 0");
  ReachableArea r;
  const std::size_t n = world.cells().size();
  r.centres.assign(n, 0);
  r.reachable.assign(n, 0);
  // A start the robot's own check refuses is refused here too (Robot::step's geometry).
  if (world.is_occupied(world.cell_of(start)) || disc_collides(world, start, robot_radius)) return r;
  const Sampling s = sampling_of(world);
  const cv::Mat space = centre_space(free_samples(world, s), s, robot_radius);
  const std::optional<cv::Point> seed = seed_sample(space, world, s, start);
  if (!seed) return r;
  r.start_valid = true;
  const cv::Mat centres = flood(space, *seed);
  r.centres = cells_touched(centres, world, s.per_cell);
  cv::Mat body = centres;
  const int k = static_cast<int>(std::ceil(robot_radius / s.step - 1e-9));
  if (k > 0) cv::dilate(centres, body, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * k + 1, 2 * k + 1}));
  const std::vector<std::uint8_t> covered = cells_touched(body, world, s.per_cell);
  for (std::size_t i = 0; i < n; ++i) {
    r.reachable[i] = (covered[i] != 0 && world.cells()[i] == World::kFree) ? 1 : 0;
    r.reachable_cells += r.reachable[i];
  }
  r.area_m2 = static_cast<double>(r.reachable_cells) * world.resolution() * world.resolution();
  return r;
}

std::vector<std::uint8_t> observable_cells(const World& world, const ReachableArea& area, double margin) {
  const int w = world.width(), h = world.height();
  std::vector<std::uint8_t> out(area.reachable.size(), 0);
  if (area.reachable.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) return out;
  const int r = static_cast<int>(std::ceil(margin / world.resolution()));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!area.reachable[static_cast<std::size_t>(y * w + x)]) continue;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          if (x + dx >= 0 && x + dx < w && y + dy >= 0 && y + dy < h)
            out[static_cast<std::size_t>((y + dy) * w + x + dx)] = 1;
    }
  }
  return out;
}

}  // namespace lookahead::exploration
