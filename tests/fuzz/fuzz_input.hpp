// SPDX-License-Identifier: MIT
// The harnesses' common part: the input as a file (the readers take paths) and the rule
// that a parser may answer bad input with an exception but never crash, hang or leak.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace lookahead::fuzz {

/// A file in the temp folder holding `size` bytes of `data`, removed on destruction.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, const std::string& suffix)
      : path_((std::filesystem::temp_directory_path() /
               ("lookahead-fuzz-" + std::to_string(getpid()) + "-" + std::to_string(counter_++) + suffix))
                  .string()) {
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~InputFile() { std::filesystem::remove(path_); }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  static inline int counter_ = 0;
  std::string path_;
};

}  // namespace lookahead::fuzz
