// SPDX-License-Identifier: MIT
#include "lookahead/slam/segslam/segment_picture.hpp"

#include <algorithm>
#include <array>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lookahead/slam/io/map_picture.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam::segslam {
namespace {

// A palette of distinguishable colours (BGR); neighbouring submaps never share one.
constexpr std::array<std::array<int, 3>, 8> kPalette{{{200, 60, 30},
                                                      {40, 40, 210},
                                                      {30, 150, 30},
                                                      {170, 40, 170},
                                                      {0, 140, 230},
                                                      {150, 150, 0},
                                                      {90, 60, 140},
                                                      {20, 100, 160}}};

cv::Scalar colour(std::size_t i) {
  const auto& c = kPalette[i % kPalette.size()];
  return {static_cast<double>(c[0]), static_cast<double>(c[1]), static_cast<double>(c[2])};
}

}  // namespace

void write_segment_picture(const std::string& png_path, const ProbabilityMap& map, const std::vector<Pose2>& odometry,
                           const SegmentedPath& path, const std::string& title) {
  if (map.width == 0 || map.height == 0) throw ParseError(png_path, 0, "", "", "empty map");
  BgrImage base = render_map_picture(map, {{odometry, {230, 140, 20}, "odometry", 1}}, {}, title);
  cv::Mat img(base.height, base.width, CV_8UC3, base.pixels.data());
  // The same pixel mapping as render_map_picture.
  const int scale = std::max(1, 800 / std::max(map.width, map.height));
  const auto to_px = [&](double x, double y) {
    return cv::Point(kLegendPanelWidth + static_cast<int>((x - map.origin_x) / map.resolution * scale),
                     static_cast<int>((map.height - (y - map.origin_y) / map.resolution) * scale));
  };
  for (std::size_t i = 0; i < path.pieces.size(); ++i) {
    std::vector<cv::Point> pts;
    for (const Pose2& p : path.pieces[i]) pts.push_back(to_px(p.x, p.y));
    if (pts.size() > 1) cv::polylines(img, pts, false, colour(i), 2, cv::LINE_AA);
  }
  for (const auto& [x, y] : path.matches) {
    const cv::Point c = to_px(x, y);
    cv::line(img, c + cv::Point(-7, -7), c + cv::Point(7, 7), cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
    cv::line(img, c + cv::Point(-7, 7), c + cv::Point(7, -7), cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
  }
  // Legend rows under the base legend (title, odometry, start).
  const int y0 = 4 + 18 * 5;
  cv::rectangle(img, cv::Rect(0, y0 - 14, kLegendPanelWidth, 40), cv::Scalar(255, 255, 255), cv::FILLED);
  for (int k = 0; k < 3; ++k)
    cv::line(img, {10 + 10 * k, y0 - 5}, {20 + 10 * k, y0 - 5}, colour(static_cast<std::size_t>(k)), 3);
  cv::putText(img, path.label, {48, y0}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {0, 0, 0}, 1, cv::LINE_AA);
  cv::putText(img, "X", {19, y0 + 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0}, 2, cv::LINE_AA);
  cv::putText(img, "match: re-entry into an old submap", {48, y0 + 18}, cv::FONT_HERSHEY_SIMPLEX, 0.45, {0, 0, 0}, 1,
              cv::LINE_AA);
  if (!cv::imwrite(png_path, img)) throw ParseError(png_path, 0, "", "", "cannot write image");
}

}  // namespace lookahead::slam::segslam
