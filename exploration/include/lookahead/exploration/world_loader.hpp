// SPDX-License-Identifier: MIT
// Loads ground-truth worlds from floor-plan files:
//   (a) a PNG/PGM with a given resolution and pixel rule,
//   (b) a ROS map_server YAML (http://wiki.ros.org/map_server, "Map format"),
//   (c) a Player/Stage .world whose floorplan model names a bitmap and its size in metres.
// Bad input throws lookahead::slam::ParseError naming the file, line, key and value.
// shared/data/floorplans/maps_index.csv and kth/SOURCES.md give each shared map's rule.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "lookahead/exploration/world.hpp"

namespace lookahead::exploration {

/// Which value of a colour pixel the rule looks at.
enum class PixelChannel {
  kFirst,  ///< the first (red) channel: Stage 4's loader
  kMean,   ///< the mean of the colour channels, alpha ignored: map_server
};

/// How a pixel becomes free or occupied. A pixel is free when its value v (0..255, after
/// `negate` turned v into 255 - v) is > free_above; everything else, including map_server's
/// "unknown" band, is occupied, because the ground truth must not let a robot into space
/// nobody mapped.
struct PixelRule {
  double free_above = 127.0;  ///< [gray level], -1..255; 127 = Stage's "> 127 is free"
  bool negate = false;        ///< for images that draw walls white
  PixelChannel channel = PixelChannel::kFirst;

  /// Stage 4 (libstage): first channel <= 127 is an obstacle.
  static PixelRule stage() { return {}; }
  /// map_server: p = (255 - v) / 255 (v / 255 when negated) is free when p < free_thresh.
  static PixelRule map_server(double free_thresh, bool negate);
  /// Only pure white is free: P2 Explore's KTH plans (0 wall, 100/102 outside, 255 free).
  static PixelRule only_white() { return {254.0, false, PixelChannel::kMean}; }
  /// Throws std::invalid_argument naming the field when a value is out of range.
  void validate() const;
};

struct ImageWorldOptions {
  double resolution = 0.05;          ///< [m/pixel], > 0
  Eigen::Vector2d origin{0.0, 0.0};  ///< lower-left corner of the image in the world [m]
  PixelRule rule;
};

struct StageWorldOptions {
  /// Overrides Stage's "> 127 is free" rule, for bitmaps Stage itself misreads (sal2.png's
  /// gray walls; Willow's map_server "unknown" 205, which Stage would make free).
  std::optional<PixelRule> rule;
  /// Cell size of the result [m], >= 0; 0 = the finer of the bitmap's two pixel sizes. Stage
  /// stretches a bitmap to `size` without keeping its aspect, so the pixels need not be square.
  double resolution = 0.0;
};

/// (a) Image file; row 0 of the image is the top of the world.
World load_image_world(const std::string& path, const ImageWorldOptions& options);
/// (b) ROS map_server YAML: image, resolution, origin, negate, occupied_thresh, free_thresh
/// and mode (trinary or scale: both call a pixel free when p < free_thresh; raw is rejected).
World load_map_yaml(const std::string& path);
/// (c) Stage .world: the first top-level floorplan/map model with a bitmap.
World load_stage_world(const std::string& path, const StageWorldOptions& options = {});

}  // namespace lookahead::exploration
