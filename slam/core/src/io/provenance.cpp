// SPDX-License-Identifier: MIT
#include "lookahead/slam/io/provenance.hpp"

#include <chrono>
#include <ctime>
#include <fstream>
#include <thread>

#include "lookahead_build_info.hpp"

namespace lookahead::slam {
namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon == std::string::npos) break;
    const std::size_t first = line.find_first_not_of(' ', colon + 1);
    return first == std::string::npos ? "" : line.substr(first);
  }
  return "unknown";
}

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace

Provenance provenance(int threads) {
  Provenance p;
  p.commit = LOOKAHEAD_COMMIT;
  p.version = LOOKAHEAD_VERSION;
  p.date_utc = now_utc();
  p.cpu = cpu_model();
  p.cores = std::thread::hardware_concurrency();
  p.threads = threads > 0 ? threads : static_cast<int>(p.cores);
  return p;
}

}  // namespace lookahead::slam
