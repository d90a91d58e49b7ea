// SPDX-License-Identifier: MIT
#include "progress_bar.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>

namespace lookahead::app {

ProgressBar::ProgressBar(std::string label, std::size_t total)
    : label_(std::move(label)),
      total_(total ? total : 1),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void ProgressBar::update(std::size_t done, const std::string& note) {
  const double frac = static_cast<double>(done) / static_cast<double>(total_);
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (!tty_) {
    const int decile = static_cast<int>(frac * 10);
    if (decile != last_decile_) {
      last_decile_ = decile;
      spdlog::info("{}: {:3.0f}% ({}/{}) {:.1f} s {}", label_, frac * 100, done, total_, elapsed, note);
    }
    return;
  }
  if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(frac * kWidth);
  const double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0.0;
  fmt::print(stderr, "\r{} [{}{}] {:3.0f}% {}/{} {:.0f}s eta {:.0f}s {}   ", label_,
             std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(kWidth - filled), '.'), frac * 100, done, total_,
             elapsed, eta, note);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  update(total_);
  if (tty_) fmt::print(stderr, "\n");
}

}  // namespace lookahead::app
