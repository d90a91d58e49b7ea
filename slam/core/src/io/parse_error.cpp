// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/parse_error.hpp"

#include <utility>

namespace lookahead::slam {
namespace {

std::string describe(const std::string& file, std::size_t line, const std::string& field, const std::string& value,
                     const std::string& reason) {
  std::string text = file;
  if (line > 0) text += ":" + std::to_string(line);
  text += ": " + reason;
  if (!field.empty()) text += " (field '" + field + "'";
  if (!field.empty() && !value.empty()) text += ", value '" + value.substr(0, 64) + "'";
  if (!field.empty()) text += ")";
  return text;
}

}  // namespace

ParseError::ParseError(std::string file, std::size_t line, std::string field, std::string value,
                       const std::string& reason)
    : std::runtime_error(describe(file, line, field, value, reason)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)),
      value_(std::move(value)),
      reason_(reason) {}

}  // namespace lookahead::slam
