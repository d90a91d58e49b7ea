// SPDX-License-Identifier: MIT
// Progress of a long run: a live bar on a terminal, a log line every 10% otherwise.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace lookahead::app {

class ProgressBar {
 public:
  ProgressBar(std::string label, std::size_t total);
  void update(std::size_t done, const std::string& note = "");
  void finish();

 private:
  std::string label_;
  std::size_t total_;
  bool tty_;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace lookahead::app
