// SPDX-License-Identifier: MIT
// Internal: turns an image file into a free/occupied mask, shared by the three loaders.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "lookahead/exploration/world.hpp"
#include "lookahead/exploration/world_loader.hpp"

namespace lookahead::exploration::detail {

/// Reads `path` and applies the rule: CV_8U, 255 = free, 0 = occupied, image rows (top first).
/// Throws ParseError(context_file, context_line, key, path) when the image cannot be read.
cv::Mat read_free_mask(const std::string& path, const PixelRule& rule, const std::string& context_file,
                       std::size_t context_line, const std::string& key);

/// Copies a mask (image rows, top first) into a World (row 0 at the bottom).
World world_from_mask(const cv::Mat& free_mask, double resolution, const Eigen::Vector2d& origin);

}  // namespace lookahead::exploration::detail
