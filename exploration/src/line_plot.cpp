// SPDX-License-Identifier: MIT
#include "lookahead/exploration/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lookahead/slam/io/parse_error.hpp"
#include "plot_axes.hpp"

namespace lookahead::exploration {
namespace {

constexpr int kLeft = 70, kRight = 20, kTop = 40, kBottom = 50;

using plot::bgr;
using plot::tick_step;

void draw_axes(cv::Mat& img, const PlotOptions& o, double x_max) {
  const int w = img.cols, h = img.rows;
  const cv::Scalar black(0, 0, 0), grey(215, 215, 215);
  const auto px = [&](double x) { return kLeft + static_cast<int>(x / x_max * (w - kLeft - kRight)); };
  const auto py = [&](double y) {
    return h - kBottom - static_cast<int>((y - o.y_min) / (o.y_max - o.y_min) * (h - kTop - kBottom));
  };
  const double xs = tick_step(x_max), ys = tick_step(o.y_max - o.y_min);
  for (double x = 0; x <= x_max + 1e-9; x += xs) {
    cv::line(img, {px(x), kTop}, {px(x), h - kBottom}, grey, 1);
    cv::putText(img, cv::format("%g", x), {px(x) - 12, h - kBottom + 18}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1,
                cv::LINE_AA);
  }
  for (double y = o.y_min; y <= o.y_max + 1e-9; y += ys) {
    cv::line(img, {kLeft, py(y)}, {w - kRight, py(y)}, grey, 1);
    cv::putText(img, cv::format("%g", y), {8, py(y) + 4}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1, cv::LINE_AA);
  }
  cv::rectangle(img, {kLeft, kTop}, {w - kRight, h - kBottom}, black, 1);
  cv::putText(img, o.title, {kLeft, 25}, cv::FONT_HERSHEY_SIMPLEX, 0.55, black, 1, cv::LINE_AA);
  cv::putText(img, o.x_label, {w / 2 - 40, h - 12}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1, cv::LINE_AA);
  cv::putText(img, o.y_label, {8, kTop - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.45, black, 1, cv::LINE_AA);
}

}  // namespace

slam::Rgb series_colour(std::size_t i) {
  static const slam::Rgb kColours[] = {{31, 119, 180},  {214, 39, 40}, {44, 160, 44},   {255, 127, 14},
                                       {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};
  return kColours[i % (sizeof(kColours) / sizeof(kColours[0]))];
}

void write_line_plot(const std::string& png_path, const std::vector<PlotSeries>& series, const PlotOptions& o) {
  cv::Mat img(o.height, o.width, CV_8UC3, cv::Scalar(255, 255, 255));
  double x_max = 1e-9;
  for (const auto& s : series) {
    for (const double x : s.x) x_max = std::max(x_max, x);
  }
  draw_axes(img, o, x_max);
  const int w = img.cols, h = img.rows;
  for (std::size_t k = 0; k < series.size(); ++k) {
    const PlotSeries& s = series[k];
    std::vector<cv::Point> pts;
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const double yc = std::clamp(s.y[i], o.y_min, o.y_max);
      pts.push_back({kLeft + static_cast<int>(s.x[i] / x_max * (w - kLeft - kRight)),
                     h - kBottom - static_cast<int>((yc - o.y_min) / (o.y_max - o.y_min) * (h - kTop - kBottom))});
    }
    if (pts.size() > 1) cv::polylines(img, pts, false, bgr(s.colour), 2, cv::LINE_AA);
    const int ly = kTop + 16 + 18 * static_cast<int>(k);
    cv::line(img, {w - kRight - 170, ly - 4}, {w - kRight - 145, ly - 4}, bgr(s.colour), 3);
    cv::putText(img, s.label, {w - kRight - 140, ly}, cv::FONT_HERSHEY_SIMPLEX, 0.42, cv::Scalar(0, 0, 0), 1,
                cv::LINE_AA);
  }
  if (!cv::imwrite(png_path, img)) throw slam::ParseError(png_path, 0, "", "", "cannot write image");
}

}  // namespace lookahead::exploration
