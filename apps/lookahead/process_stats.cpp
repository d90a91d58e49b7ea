// SPDX-License-Identifier: MIT
#include "process_stats.hpp"

#include <fstream>
#include <string>

namespace lookahead::app {

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      status >> kb;
      return kb / 1024.0;
    }
    status.ignore(1 << 12, '\n');
  }
  return 0.0;
}

}  // namespace lookahead::app
