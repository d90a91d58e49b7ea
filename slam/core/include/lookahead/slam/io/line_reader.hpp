// SPDX-License-Identifier: MIT
// Reads a text file line by line, gzip-compressed or not (zlib detects which).
#pragma once

#include <cstddef>
#include <string>

namespace lookahead::slam {

class LineReader {
 public:
  /// Throws ParseError when the file cannot be opened.
  explicit LineReader(const std::string& path);
  ~LineReader();
  LineReader(const LineReader&) = delete;
  LineReader& operator=(const LineReader&) = delete;

  /// Reads the next line (without its newline); false at the end of the file.
  bool next(std::string& line);
  /// 1-based number of the line last returned by next().
  [[nodiscard]] std::size_t line_number() const { return line_number_; }

 private:
  bool fill();

  std::string path_;
  void* file_ = nullptr;  // gzFile; kept opaque so zlib stays out of this header
  std::string buffer_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
  bool eof_ = false;
};

}  // namespace lookahead::slam
