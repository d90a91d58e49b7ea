// SPDX-License-Identifier: MIT
#include "progress_bar.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace lookahead::app {

ProgressBar::ProgressBar(std::string label, std::size_t total)
    : label_(std::move(label)),
      total_(total ? total : 1),
      tty_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

namespace {

std::string duration(double seconds) {
  const auto s = static_cast<long>(seconds + 0.5);
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s / 60) % 60);
}

}  // namespace

void ProgressBar::update(std::size_t done, const std::string& note) {
  shown_ = std::max(shown_, std::min(done, total_));
  const double frac = static_cast<double>(shown_) / static_cast<double>(total_);
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(shown_) / elapsed : 0.0;
  const std::string left = rate > 0 ? duration(static_cast<double>(total_ - shown_) / rate) : "?";
  if (!tty_) {
    const int decile = static_cast<int>(frac * 10);
    if (decile > last_decile_) {
      last_decile_ = decile;
      spdlog::info("{}: {:3.0f}% ({}/{}) elapsed {}, {:.3g}/s, about {} left {}", label_, frac * 100, shown_, total_,
                   duration(elapsed), rate, left, note);
    }
    return;
  }
  if (now - last_draw_ < std::chrono::milliseconds(100) && shown_ < total_) return;
  last_draw_ = now;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(frac * kWidth);
  fmt::print(stderr, "\r{} [{}{}] {:3.0f}% {}/{} {} {:.3g}/s eta {} {}\x1b[K", label_,
             std::string(static_cast<std::size_t>(filled), '#'),
             std::string(static_cast<std::size_t>(kWidth - filled), '.'), frac * 100, shown_, total_, duration(elapsed),
             rate, left, note);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  update(total_);
  if (tty_) fmt::print(stderr, "\n");
}

}  // namespace lookahead::app
