// SPDX-License-Identifier: MIT
#include "study_progress_log.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <filesystem>

namespace lookahead::app {

std::string format_duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) return fmt::format("{} h {:02d} min", s / 3600, (s % 3600) / 60);
  if (s >= 60) return fmt::format("{} min {:02d} s", s / 60, s % 60);
  return fmt::format("{} s", s);
}

StudyProgressLog::StudyProgressLog(const std::string& path, std::string what) : path_(path), what_(std::move(what)) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  out_.open(path, std::ios::app);
}

void StudyProgressLog::update(const exploration::StudyProgress& p) {
  const std::time_t now = std::time(nullptr);
  std::string line = fmt::format("{:%Y-%m-%d %H:%M:%S} {}: {}/{} done", fmt::localtime(now), what_, p.done, p.total);
  if (p.reused > 0) line += fmt::format(" ({} finished earlier)", p.reused);
  if (!p.last_run.empty()) line += ", last " + p.last_run;
  line += fmt::format(", elapsed {}", format_duration(p.elapsed));
  if (p.done > 0 && p.done < p.total) {
    const double left = p.elapsed / static_cast<double>(p.done) * static_cast<double>(p.total - p.done);
    line += ", about " + format_duration(left) + " left";
  }
  if (!p.in_flight.empty()) {
    line += fmt::format("; in flight ({}):", p.in_flight.size());
    for (const std::string& id : p.in_flight) line += " " + id;
  }
  out_ << line << std::endl;  // flushed: read while the study runs
}

}  // namespace lookahead::app
