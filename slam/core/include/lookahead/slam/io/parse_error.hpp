// SPDX-License-Identifier: MIT
// The one exception bad input raises: it names the file, the line, the field and the value.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace lookahead::slam {

class ParseError : public std::runtime_error {
 public:
  ParseError(std::string file, std::size_t line, std::string field, std::string value, const std::string& reason);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] std::size_t line() const { return line_; }
  [[nodiscard]] const std::string& field() const { return field_; }
  [[nodiscard]] const std::string& value() const { return value_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  std::size_t line_;
  std::string field_;
  std::string value_;
  std::string reason_;
};

}  // namespace lookahead::slam
