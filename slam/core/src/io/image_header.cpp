// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/image_header.hpp"

#include <array>
#include <cctype>
#include <fstream>
#include <optional>
#include <utility>

#include "lookahead/slam/io/parse_error.hpp"
#include "lookahead/slam/limits/input_limits.hpp"

namespace lookahead::slam {
namespace {

using Size = std::pair<std::int64_t, std::int64_t>;

/// Next decimal number of a Netpbm header (whitespace and # comments between), or nullopt.
std::optional<std::int64_t> netpbm_number(std::istream& in) {
  int c = in.get();
  while (c != EOF && (std::isspace(c) || c == '#')) {
    if (c == '#') {
      while (c != EOF && c != '\n') c = in.get();
    }
    c = in.get();
  }
  if (c == EOF || !std::isdigit(c)) return std::nullopt;
  std::int64_t v = 0;
  for (; c != EOF && std::isdigit(c); c = in.get()) {
    if (v > (std::int64_t{1} << 40)) return std::nullopt;  // far over any limit already
    v = v * 10 + (c - '0');
  }
  return v;
}

std::optional<Size> netpbm_size(std::istream& in) {
  const auto w = netpbm_number(in);
  const auto h = w ? netpbm_number(in) : std::nullopt;
  if (!w || !h) return std::nullopt;
  return Size{*w, *h};
}

std::int64_t big_endian32(const unsigned char* b) {
  return (std::int64_t{b[0]} << 24) | (std::int64_t{b[1]} << 16) | (std::int64_t{b[2]} << 8) | b[3];
}

}  // namespace

void check_image_size(std::int64_t width, std::int64_t height, const std::string& context_file, std::size_t line,
                      const std::string& key) {
  const std::string value = std::to_string(width) + " x " + std::to_string(height);
  if (width <= 0 || height <= 0) throw ParseError(context_file, line, key, value, "image has no pixels");
  if (width > limits::kMaxImagePixels / height) {
    throw ParseError(context_file, line, key, value, "image over 8192 x 8192 pixels (limits::kMaxImagePixels)");
  }
}

void check_image_header(const std::string& image_path, const std::string& context_file, std::size_t line,
                        const std::string& key) {
  std::ifstream in(image_path, std::ios::binary);
  std::array<unsigned char, 24> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), 2)) return;  // the decoder reports it
  if (head[0] == 'P' && head[1] >= '1' && head[1] <= '6') {
    const std::optional<Size> size = netpbm_size(in);
    if (!size) throw ParseError(context_file, line, key, image_path, "malformed Netpbm header");
    check_image_size(size->first, size->second, context_file, line, key);
    return;
  }
  constexpr std::array<unsigned char, 8> kPng{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (head[0] == kPng[0] && head[1] == kPng[1] && in.read(reinterpret_cast<char*>(head.data() + 2), 22)) {
    // PNG: signature (8), IHDR length and type (8), then width and height (4 each).
    check_image_size(big_endian32(&head[16]), big_endian32(&head[20]), context_file, line, key);
  }
}

}  // namespace lookahead::slam
