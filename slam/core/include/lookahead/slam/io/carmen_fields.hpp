// SPDX-License-Identifier: MIT
// Tokens of one CARMEN line with typed, checked access: every failure names the field.
#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam::carmen {

class Fields {
 public:
  Fields(const std::string& file, std::size_t line, std::string_view text) : file_(file), line_(line) {
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      const std::size_t start = i;
      while (i < text.size() && text[i] != ' ' && text[i] != '\t') ++i;
      if (i > start) tokens_.push_back(text.substr(start, i - start));
    }
  }

  [[nodiscard]] std::size_t size() const { return tokens_.size(); }
  [[nodiscard]] std::string_view token(std::size_t i) const { return tokens_[i]; }

  void require(std::size_t count, const char* what) const {
    if (tokens_.size() < count) {
      fail(what, std::to_string(tokens_.size()) + " fields", "too few fields: need at least " + std::to_string(count));
    }
  }

  /// A finite number, or (allow_non_finite) also nan/inf.
  [[nodiscard]] double number(std::size_t i, const char* name, bool allow_non_finite = false) const {
    if (i >= tokens_.size()) fail(name, "", "missing field");
    const std::string_view t = tokens_[i];
    double v = 0.0;
    const char* begin = t.data();
    if (!t.empty() && t.front() == '+') ++begin;  // from_chars rejects a leading '+'
    const auto [end, ec] = std::from_chars(begin, t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail(name, t, "not a number");
    if (!allow_non_finite && !std::isfinite(v)) fail(name, t, "not a finite number");
    return v;
  }

  [[nodiscard]] std::size_t count(std::size_t i, const char* name, std::size_t max) const {
    const double v = number(i, name);
    if (v < 0 || v != std::floor(v) || v > static_cast<double>(max)) {
      fail(name, tokens_[i], "not a count in 0.." + std::to_string(max));
    }
    return static_cast<std::size_t>(v);
  }

  [[noreturn]] void fail(const char* field, std::string_view value, const std::string& why) const {
    throw ParseError(file_, line_, field, std::string(value), why);
  }

 private:
  const std::string& file_;
  std::size_t line_;
  std::vector<std::string_view> tokens_;
};

}  // namespace lookahead::slam::carmen
