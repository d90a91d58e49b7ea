// SPDX-License-Identifier: MIT
// The size an image file claims, read from its header before any decoder allocates for it:
// a map or world image is refused up front when it claims more than limits::kMaxImagePixels.
// Netpbm (P1-P6: PBM/PGM/PPM, what map_server writes) and PNG headers are read; other
// formats are left to the decoder, whose result is checked after reading.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace lookahead::slam {

/// Throws ParseError (file `context_file`, line `line`, field `key`, value "W x H") when the
/// header of `image_path` claims a size over limits::kMaxImagePixels or is malformed.
void check_image_header(const std::string& image_path, const std::string& context_file, std::size_t line,
                        const std::string& key);

/// The same check on a decoded image's size.
void check_image_size(std::int64_t width, std::int64_t height, const std::string& context_file, std::size_t line,
                      const std::string& key);

}  // namespace lookahead::slam
