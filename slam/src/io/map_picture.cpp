// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/map_picture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {

cv::Scalar bgr(Rgb c) { return {static_cast<double>(c.b), static_cast<double>(c.g), static_cast<double>(c.r)}; }

cv::Mat render_occupancy(const ProbabilityMap& map, int scale) {
  cv::Mat img(map.height * scale, map.width * scale, CV_8UC3);
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double p = map.at(x, y);
      cv::Vec3b v;
      if (p < 0) {
        v = {228, 220, 214};  // unknown: pale blue-grey, so it is not mistaken for free space
      } else {
        const auto g = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - p)));
        v = {g, g, g};
      }
      cv::rectangle(img, cv::Rect(x * scale, (map.height - 1 - y) * scale, scale, scale),
                    cv::Scalar(v[0], v[1], v[2]), cv::FILLED);
    }
  }
  return img;
}

}  // namespace

void write_map_picture(const std::string& png_path, const ProbabilityMap& map,
                       const std::vector<PicturePath>& paths, const std::string& title) {
  if (map.width == 0 || map.height == 0) throw ParseError(png_path, 0, "", "", "empty map");
  // Small maps are scaled up so a person can see the cells; big ones stay 1:1.
  const int scale = std::max(1, 800 / std::max(map.width, map.height));
  cv::Mat img = render_occupancy(map, scale);
  const auto to_px = [&](const Pose2& p) {
    return cv::Point(static_cast<int>((p.x - map.origin_x) / map.resolution * scale),
                     static_cast<int>((map.height - (p.y - map.origin_y) / map.resolution) * scale));
  };
  for (const PicturePath& path : paths) {
    std::vector<cv::Point> pts;
    for (const Pose2& p : path.poses) pts.push_back(to_px(p));
    if (pts.size() > 1) {
      cv::polylines(img, pts, false, bgr(path.colour), path.thickness, cv::LINE_AA);
    }
  }
  if (!paths.empty() && !paths.front().poses.empty()) {
    cv::circle(img, to_px(paths.front().poses.front()), 6, cv::Scalar(40, 160, 40), cv::FILLED);
  }
  // Legend in the top-left corner on a white box.
  const int line_h = 18;
  const int box_h = line_h * static_cast<int>(paths.size() + 2) + 6;
  cv::rectangle(img, cv::Rect(4, 4, 330, box_h), cv::Scalar(255, 255, 255), cv::FILLED);
  cv::putText(img, title, {10, 4 + line_h}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  int row = 2;
  for (const PicturePath& path : paths) {
    const int yline = 4 + line_h * row++;
    cv::line(img, {10, yline - 5}, {40, yline - 5}, bgr(path.colour), 3);
    cv::putText(img, path.label, {48, yline}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
  cv::circle(img, {25, 4 + line_h * row - 5}, 5, cv::Scalar(40, 160, 40), cv::FILLED);
  cv::putText(img, "start", {48, 4 + line_h * row}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  if (!cv::imwrite(png_path, img)) throw ParseError(png_path, 0, "", "", "cannot write image");
}

}  // namespace lookahead::slam
