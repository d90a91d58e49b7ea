// SPDX-License-Identifier: MIT
// Progress of a long run: a live bar on a terminal (elapsed, rate, estimated time left), a
// plain log line every 10 % otherwise. The bar never goes backwards: a report of fewer items
// than already shown (parallel workers report out of order) keeps the bar where it is.
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
  std::size_t shown_ = 0;  ///< the most items reported so far
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace lookahead::app
