// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>

namespace lookahead::app {

/// Peak resident memory of this process so far [MB] (VmHWM), 0 where unavailable.
double peak_memory_mb();

/// Wall-clock seconds since `start`.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace lookahead::app
