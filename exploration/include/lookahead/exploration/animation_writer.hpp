// SPDX-License-Identifier: MIT
// An MP4 of a mission: one frame per snapshot, every frame scaled to the first one's size.
#pragma once

#include <memory>
#include <string>

#include "lookahead/slam/io/map_picture.hpp"

namespace lookahead::exploration {

class AnimationWriter {
 public:
  /// Opens `path` (MP4, MPEG-4 part 2) at `fps` frames per second; throws ParseError when
  /// the video cannot be written.
  AnimationWriter(const std::string& path, double fps);
  ~AnimationWriter();
  AnimationWriter(const AnimationWriter&) = delete;
  AnimationWriter& operator=(const AnimationWriter&) = delete;

  void add(const slam::BgrImage& frame);
  /// Finishes the file (also done by the destructor).
  void close();
  [[nodiscard]] int frames() const { return frames_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  double fps_;
  int frames_ = 0;
};

}  // namespace lookahead::exploration
