// SPDX-License-Identifier: MIT
#include "lookahead/exploration/world_reachability.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace lookahead::exploration {
namespace {

// 255 where the robot centre fits, with a one-cell occupied frame (outside = occupied).
cv::Mat centre_space(const World& w, double radius) {
  cv::Mat free(w.height() + 2, w.width() + 2, CV_8U, cv::Scalar(0));
  for (int y = 0; y < w.height(); ++y) {
    for (int x = 0; x < w.width(); ++x) {
      if (!w.is_occupied(slam::CellIndex{x, y})) free.at<std::uint8_t>(y + 1, x + 1) = 255;
    }
  }
  if (radius <= 0) return free;
  cv::Mat dist;
  cv::distanceTransform(free, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const float min_px = static_cast<float>(radius / w.resolution() + std::sqrt(0.5));
  cv::Mat fits;
  cv::compare(dist, min_px, fits, cv::CMP_GE);
  return fits;
}

std::size_t flood_fill(const cv::Mat& space, slam::CellIndex start, std::vector<std::uint8_t>& out, int width) {
  std::vector<slam::CellIndex> stack{start};
  out[static_cast<std::size_t>(start.y) * width + start.x] = 1;
  std::size_t count = 0;
  const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const slam::CellIndex c = stack.back();
    stack.pop_back();
    ++count;
    for (int k = 0; k < 4; ++k) {
      const slam::CellIndex n{c.x + dx[k], c.y + dy[k]};
      // The frame keeps n inside `space`; its cells are 0, so they stop the fill.
      if (space.at<std::uint8_t>(n.y + 1, n.x + 1) == 0) continue;
      auto& seen = out[static_cast<std::size_t>(n.y) * width + n.x];
      if (seen) continue;
      seen = 1;
      stack.push_back(n);
    }
  }
  return count;
}

}  // namespace

ReachableArea reachable_free_area(const World& world, const Eigen::Vector2d& start, double robot_radius) {
  if (!(robot_radius >= 0)) throw std::invalid_argument("robot_radius must be >= 0");
  ReachableArea r;
  const std::size_t n = world.cells().size();
  r.centres.assign(n, 0);
  r.reachable.assign(n, 0);
  const cv::Mat space = centre_space(world, robot_radius);
  const slam::CellIndex s = world.cell_of(start);
  if (!world.contains(s) || space.at<std::uint8_t>(s.y + 1, s.x + 1) == 0) return r;
  r.start_valid = true;
  flood_fill(space, s, r.centres, world.width());
  cv::Mat body(world.height(), world.width(), CV_8U, r.centres.data());
  cv::Mat grown = body.clone();
  const int k = static_cast<int>(std::ceil(robot_radius / world.resolution()));
  if (k > 0) {
    cv::dilate(body, grown, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * k + 1, 2 * k + 1}));
  }
  for (std::size_t i = 0; i < n; ++i) {
    r.reachable[i] = (grown.data[i] != 0 && world.cells()[i] == World::kFree) ? 1 : 0;
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
