// SPDX-License-Identifier: MIT
// A uniquely named temporary file or folder, removed when the test ends.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

namespace lookahead::slam::test {

class TempPath {
 public:
  explicit TempPath(const std::string& suffix = "") {
    static std::atomic<int> counter{0};
    path_ = (std::filesystem::temp_directory_path() /
             ("lookahead-test-" + std::to_string(getpid()) + "-" + std::to_string(counter++) + suffix))
                .string();
  }
  ~TempPath() { std::filesystem::remove_all(path_); }
  TempPath(const TempPath&) = delete;
  TempPath& operator=(const TempPath&) = delete;
  [[nodiscard]] const std::string& str() const { return path_; }
  void write(const std::string& text) const { std::ofstream(path_, std::ios::binary) << text; }

 private:
  std::string path_;
};

}  // namespace lookahead::slam::test
