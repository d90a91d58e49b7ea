// SPDX-License-Identifier: MIT
#include "lookahead/exploration/study_bar_plot.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lookahead/exploration/line_plot.hpp"
#include "lookahead/slam/io/parse_error.hpp"
#include "plot_axes.hpp"

namespace lookahead::exploration {
namespace {

constexpr int kLeft = 70, kRight = 170, kTop = 55, kBottom = 60;  // room for title, ticks, legend
const cv::Scalar kBlack(0, 0, 0), kGrey(215, 215, 215);

using plot::bgr;
using plot::tick_step;

double axis_top(const BarChart& c) {
  double top = 0.0;
  for (const auto& group : c.bars)
    for (const Bar& b : group)
      if (b.present) top = std::max(top, b.value + b.whisker);
  if (top <= 0) return 1.0;
  const double step = tick_step(top * 1.05);
  return std::ceil(top * 1.05 / step) * step;
}

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = 0.42) {
  cv::putText(img, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, kBlack, 1, cv::LINE_AA);
}

void draw_frame(cv::Mat& img, const BarChart& c, double top) {
  const int h = img.rows, w = img.cols;
  const double step = tick_step(top);
  for (double y = 0; y <= top + 1e-9; y += step) {
    const int py = h - kBottom - static_cast<int>(y / top * (h - kTop - kBottom));
    cv::line(img, {kLeft, py}, {w - kRight, py}, kGrey, 1);
    text(img, cv::format("%g", y), {8, py + 4}, 0.4);
  }
  cv::rectangle(img, {kLeft, kTop}, {w - kRight, h - kBottom}, kBlack, 1);
  text(img, c.title, {8, 22}, 0.55);
  text(img, c.y_label, {8, kTop - 10}, 0.45);
  for (std::size_t s = 0; s < c.series.size(); ++s) {
    const int ly = kTop + 16 + 18 * static_cast<int>(s);
    cv::rectangle(img, {w - kRight + 10, ly - 10}, {w - kRight + 30, ly}, bgr(series_colour(s)), cv::FILLED);
    text(img, c.series[s], {w - kRight + 36, ly});
  }
}

void draw_group(cv::Mat& img, const BarChart& c, std::size_t g, double top) {
  const int h = img.rows, plot_w = img.cols - kLeft - kRight;
  const double group_w = static_cast<double>(plot_w) / static_cast<double>(c.groups.size());
  const double bar_w = group_w * 0.8 / static_cast<double>(std::max<std::size_t>(1, c.series.size()));
  const double x0 = kLeft + group_w * static_cast<double>(g) + group_w * 0.1;
  const auto py = [&](double y) {
    return h - kBottom - static_cast<int>(std::clamp(y, 0.0, top) / top * (h - kTop - kBottom));
  };
  for (std::size_t s = 0; s < c.series.size() && s < c.bars[g].size(); ++s) {
    const Bar& b = c.bars[g][s];
    const int left = static_cast<int>(x0 + bar_w * static_cast<double>(s)),
              right = static_cast<int>(x0 + bar_w * (static_cast<double>(s) + 0.9));
    const int mid = (left + right) / 2;
    if (!b.present) {
      text(img, "n/a", {left, h - kBottom - 6}, 0.35);
      continue;
    }
    cv::rectangle(img, {left, py(b.value)}, {right, h - kBottom}, bgr(series_colour(s)), cv::FILLED);
    if (b.whisker > 0) {
      const int lo = py(b.value - b.whisker), hi = py(b.value + b.whisker);
      cv::line(img, {mid, lo}, {mid, hi}, kBlack, 1, cv::LINE_AA);
      cv::line(img, {mid - 4, lo}, {mid + 4, lo}, kBlack, 1);
      cv::line(img, {mid - 4, hi}, {mid + 4, hi}, kBlack, 1);
    }
    if (b.count >= 0) text(img, "n=" + std::to_string(b.count), {left, py(b.value + b.whisker) - 4}, 0.35);
  }
  // Long labels (KTH plan numbers) are cut to what fits under the group.
  const std::size_t fits = static_cast<std::size_t>(std::max(3.0, group_w / 7.5));
  const std::string label = c.groups[g].size() > fits ? c.groups[g].substr(0, fits - 1) + "~" : c.groups[g];
  text(img, label, {static_cast<int>(x0), h - kBottom + 18}, 0.38);
}

}  // namespace

void write_bar_chart(const std::string& png_path, const BarChart& c) {
  cv::Mat img(c.height, c.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const double top = axis_top(c);
  draw_frame(img, c, top);
  for (std::size_t g = 0; g < c.groups.size() && g < c.bars.size(); ++g) draw_group(img, c, g, top);
  if (!cv::imwrite(png_path, img)) throw slam::ParseError(png_path, 0, "", "", "cannot write image");
}

}  // namespace lookahead::exploration
