// SPDX-License-Identifier: MIT
#include "world_image.hpp"

#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "lookahead/slam/io/image_header.hpp"
#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {

PixelRule PixelRule::map_server(double free_thresh, bool negate) {
  // p < t  <=>  (255 - v) / 255 < t  <=>  v > 255 (1 - t); negation is applied to v first.
  return {255.0 * (1.0 - free_thresh), negate, PixelChannel::kMean};
}

void PixelRule::validate() const {
  if (!(free_above >= -1.0 && free_above <= 255.0)) {
    throw std::invalid_argument("PixelRule.free_above must be in -1..255, got " + std::to_string(free_above));
  }
}

namespace detail {
namespace {

double pixel_value(const cv::Mat& image, int r, int c, PixelChannel channel) {
  const int n = image.channels();
  const std::uint8_t* p = image.ptr<std::uint8_t>(r) + c * n;
  if (n <= 2) return p[0];  // gray, or gray + alpha
  // OpenCV stores colour as BGR(A): the first channel of the file is index 2.
  if (channel == PixelChannel::kFirst) return p[2];
  return (p[0] + p[1] + p[2]) / 3.0;
}

}  // namespace

cv::Mat read_free_mask(const std::string& path, const PixelRule& rule, const std::string& context_file,
                       std::size_t context_line, const std::string& key) {
  rule.validate();
  slam::check_image_header(path, context_file, context_line, key);
  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {  // a header OpenCV's decoder refuses
    throw slam::ParseError(context_file, context_line, key, path, "cannot read image: " + e.msg);
  }
  if (image.empty()) {
    throw slam::ParseError(context_file, context_line, key, path, "cannot read image");
  }
  slam::check_image_size(image.cols, image.rows, context_file, context_line, key);
  if (image.depth() == CV_16U) image.convertTo(image, CV_8U, 1.0 / 257.0);
  if (image.depth() != CV_8U) {
    throw slam::ParseError(context_file, context_line, key, path, "unsupported pixel depth");
  }
  cv::Mat mask(image.rows, image.cols, CV_8U);
  for (int r = 0; r < image.rows; ++r) {
    auto* out = mask.ptr<std::uint8_t>(r);
    for (int c = 0; c < image.cols; ++c) {
      double v = pixel_value(image, r, c, rule.channel);
      if (rule.negate) v = 255.0 - v;
      out[c] = v > rule.free_above ? 255 : 0;
    }
  }
  return mask;
}

World world_from_mask(const cv::Mat& free_mask, double resolution, const Eigen::Vector2d& origin) {
  World world(free_mask.cols, free_mask.rows, resolution, origin, World::kOccupied);
  for (int r = 0; r < free_mask.rows; ++r) {
    const auto* in = free_mask.ptr<std::uint8_t>(r);
    const int y = free_mask.rows - 1 - r;  // image top row = world top row
    for (int x = 0; x < free_mask.cols; ++x) {
      if (in[x] != 0) world.set({x, y}, World::kFree);
    }
  }
  return world;
}

}  // namespace detail
}  // namespace lookahead::exploration
