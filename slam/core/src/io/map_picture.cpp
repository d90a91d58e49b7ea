// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/map_picture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

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
      if (p == -0.5) {
        v = {200, 188, 180};  // unknown, but a true wall there (exploration pictures)
      } else if (p < 0) {
        v = {228, 220, 214};  // unknown: pale blue-grey, so it is not mistaken for free space
      } else {
        const auto g = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - p)));
        v = {g, g, g};
      }
      cv::rectangle(img, cv::Rect(x * scale, (map.height - 1 - y) * scale, scale, scale), cv::Scalar(v[0], v[1], v[2]),
                    cv::FILLED);
    }
  }
  return img;
}

void draw_legend(cv::Mat& img, const std::vector<PicturePath>& paths, const std::vector<PicturePoints>& points,
                 const std::string& title, bool start) {
  const int line_h = 18;
  const int rows = static_cast<int>(paths.size() + points.size()) + (start ? 2 : 1);
  cv::rectangle(img, cv::Rect(0, 0, kLegendPanelWidth, std::max(img.rows, line_h * rows + 6)),
                cv::Scalar(255, 255, 255), cv::FILLED);
  const auto text = [&](const std::string& t, int row) {
    cv::putText(img, t, {48, 4 + line_h * row}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  };
  cv::putText(img, title, {10, 4 + line_h}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  int row = 2;
  for (const PicturePath& path : paths) {
    cv::line(img, {10, 4 + line_h * row - 5}, {40, 4 + line_h * row - 5}, bgr(path.colour), 3);
    text(path.label, row++);
  }
  for (const PicturePoints& set : points) {
    cv::circle(img, {25, 4 + line_h * row - 5}, 4, bgr(set.colour), cv::FILLED);
    text(set.label, row++);
  }
  if (!start) return;
  cv::circle(img, {25, 4 + line_h * row - 5}, 5, cv::Scalar(40, 160, 40), cv::FILLED);
  text("start", row);
}

}  // namespace

BgrImage render_map_picture(const ProbabilityMap& map, const std::vector<PicturePath>& paths,
                            const std::vector<PicturePoints>& points, const std::string& title) {
  if (map.width == 0 || map.height == 0) throw std::invalid_argument("render_map_picture: empty map");
  const int scale = std::max(1, 800 / std::max(map.width, map.height));
  cv::Mat img = render_occupancy(map, scale);
  const auto to_px = [&](double x, double y) {
    return cv::Point(static_cast<int>((x - map.origin_x) / map.resolution * scale),
                     static_cast<int>((map.height - (y - map.origin_y) / map.resolution) * scale));
  };
  for (const PicturePoints& set : points) {
    for (const auto& [x, y] : set.points) {
      if (set.fill_cells) {
        const int cx = static_cast<int>(std::floor((x - map.origin_x) / map.resolution));
        const int cy = map.height - 1 - static_cast<int>(std::floor((y - map.origin_y) / map.resolution));
        cv::rectangle(img, cv::Rect(cx * scale, cy * scale, scale, scale), bgr(set.colour), cv::FILLED);
      } else {
        cv::circle(img, to_px(x, y), set.radius, bgr(set.colour), cv::FILLED);
      }
    }
  }
  for (const PicturePath& path : paths) {
    std::vector<cv::Point> pts;
    for (const Pose2& p : path.poses) pts.push_back(to_px(p.x, p.y));
    if (pts.size() > 1) cv::polylines(img, pts, false, bgr(path.colour), path.thickness, cv::LINE_AA);
  }
  const bool start = !paths.empty() && paths.front().marks_start && !paths.front().poses.empty();
  if (start) {
    const Pose2& s0 = paths.front().poses.front();
    cv::circle(img, to_px(s0.x, s0.y), 6, cv::Scalar(40, 160, 40), cv::FILLED);
  }
  // The legend gets a panel of its own left of the map: drawn over the map it hid the
  // corner of every building that fills its picture.
  cv::Mat framed(img.rows, img.cols + kLegendPanelWidth, img.type(), cv::Scalar(255, 255, 255));
  img.copyTo(framed(cv::Rect(kLegendPanelWidth, 0, img.cols, img.rows)));
  draw_legend(framed, paths, points, title, start);
  img = framed;
  BgrImage out;
  out.width = img.cols;
  out.height = img.rows;
  out.pixels.assign(img.data, img.data + img.total() * img.elemSize());
  return out;
}

void write_map_picture(const std::string& png_path, const ProbabilityMap& map, const std::vector<PicturePath>& paths,
                       const std::string& title, const std::vector<PicturePoints>& points) {
  if (map.width == 0 || map.height == 0) throw ParseError(png_path, 0, "", "", "empty map");
  BgrImage image = render_map_picture(map, paths, points, title);
  const cv::Mat img(image.height, image.width, CV_8UC3, image.pixels.data());
  if (!cv::imwrite(png_path, img)) throw ParseError(png_path, 0, "", "", "cannot write image");
}

}  // namespace lookahead::slam
