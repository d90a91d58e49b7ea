// SPDX-License-Identifier: MIT
#include "lookahead/exploration/animation_writer.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::exploration {

struct AnimationWriter::Impl {
  cv::VideoWriter writer;
  cv::Size size;
};

AnimationWriter::AnimationWriter(const std::string& path, double fps)
    : impl_(std::make_unique<Impl>()), path_(path), fps_(fps) {}

AnimationWriter::~AnimationWriter() { close(); }

void AnimationWriter::add(const slam::BgrImage& frame) {
  if (frame.width == 0 || frame.height == 0) return;
  cv::Mat img(frame.height, frame.width, CV_8UC3, const_cast<std::uint8_t*>(frame.pixels.data()));
  if (!impl_->writer.isOpened()) {
    // Even sizes: MPEG-4 encoders reject odd frame dimensions.
    impl_->size = {frame.width & ~1, frame.height & ~1};
    impl_->writer.open(path_, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), fps_, impl_->size);
    if (!impl_->writer.isOpened()) throw slam::ParseError(path_, 0, "", "", "cannot open video for writing");
  }
  cv::Mat out;
  cv::resize(img, out, impl_->size, 0, 0, cv::INTER_AREA);
  impl_->writer.write(out);
  ++frames_;
}

void AnimationWriter::close() {
  if (impl_ && impl_->writer.isOpened()) impl_->writer.release();
}

}  // namespace lookahead::exploration
