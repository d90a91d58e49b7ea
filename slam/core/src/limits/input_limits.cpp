// SPDX-License-Identifier: MIT
#include "lookahead/slam/limits/input_limits.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace lookahead::slam::limits {
namespace {

/// MemAvailable in bytes, or the largest value when /proc/meminfo does not say.
std::uint64_t mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string key;
    std::uint64_t kib = 0;
    if (fields >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return std::numeric_limits<std::uint64_t>::max();
}

std::string gigabytes(double bytes) { return fmt::format("{:.2f} GB", bytes / 1e9); }

}  // namespace

std::uint64_t available_memory_bytes() {
  std::uint64_t bytes = mem_available();
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    bytes = std::min<std::uint64_t>(bytes, as.rlim_cur);
  }
  return bytes;
}

void check_memory(double bytes, const std::string& what) {
  const auto available = static_cast<double>(available_memory_bytes());
  if (bytes <= available) return;
  throw ResourceLimitError(fmt::format("{} need about {}, more than the {} this machine has available", what,
                                       gigabytes(bytes), gigabytes(available)));
}

}  // namespace lookahead::slam::limits
