// SPDX-License-Identifier: MIT
// Where a run's figures come from: the commit the binary was built from, the machine and the
// thread count. Every run.json carries it (docs/results.md quotes figures with it).
#pragma once

#include <string>

namespace lookahead::slam {

struct Provenance {
  std::string commit;    ///< `git describe --always --dirty` at build time, or "unknown"
  std::string version;   ///< the project version
  std::string date_utc;  ///< when the run started, ISO 8601
  std::string cpu;       ///< model name from /proc/cpuinfo
  unsigned cores = 0;    ///< hardware threads of the machine
  int threads = 0;       ///< worker threads the run used
};

/// `threads` as the options say it (0 = every core); recorded as the count used.
Provenance provenance(int threads);

}  // namespace lookahead::slam
