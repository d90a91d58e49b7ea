// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/line_reader.hpp"

#include <zlib.h>

#include "lookahead/slam/io/parse_error.hpp"

namespace lookahead::slam {
namespace {
constexpr unsigned kChunk = 1u << 16;
}

LineReader::LineReader(const std::string& path) : path_(path) {
  // gzopen reads plain files transparently, so one reader serves .log and .log.gz.
  gzFile f = gzopen(path.c_str(), "rb");
  if (f == nullptr) throw ParseError(path, 0, "", "", "cannot open file");
  gzbuffer(f, kChunk);
  file_ = f;
}

LineReader::~LineReader() {
  if (file_ != nullptr) gzclose(static_cast<gzFile>(file_));
}

bool LineReader::fill() {
  if (eof_) return false;
  buffer_.erase(0, pos_);
  pos_ = 0;
  const std::size_t old = buffer_.size();
  buffer_.resize(old + kChunk);
  const int n = gzread(static_cast<gzFile>(file_), buffer_.data() + old, kChunk);
  if (n < 0) {
    int code = 0;
    const char* msg = gzerror(static_cast<gzFile>(file_), &code);
    throw ParseError(path_, line_number_ + 1, "", "", std::string("read error: ") + msg);
  }
  buffer_.resize(old + static_cast<std::size_t>(n));
  if (n == 0) eof_ = true;
  return n > 0;
}

bool LineReader::next(std::string& line) {
  for (;;) {
    const std::size_t nl = buffer_.find('\n', pos_);
    if (nl != std::string::npos) {
      line.assign(buffer_, pos_, nl - pos_);
      pos_ = nl + 1;
      break;
    }
    if (!fill()) {
      if (pos_ >= buffer_.size()) return false;
      line.assign(buffer_, pos_, std::string::npos);  // last line without a newline
      pos_ = buffer_.size();
      break;
    }
  }
  if (!line.empty() && line.back() == '\r') line.pop_back();
  ++line_number_;
  return true;
}

}  // namespace lookahead::slam
