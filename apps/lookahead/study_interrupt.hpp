// SPDX-License-Identifier: MIT
// Ctrl-C or SIGTERM during a local study: the runs in flight are abandoned (their staging
// folders never look finished), and the results of every finished run are written before the
// process exits, so an interrupted study still tells what it found. SIGINT and SIGTERM are
// blocked in every thread and received by one watcher thread (sigwait), so the work done on
// them is ordinary code, not a signal handler.
#pragma once

#include <atomic>
#include <functional>
#include <thread>

namespace lookahead::app {

class StudyInterrupt {
 public:
  /// From now on SIGINT and SIGTERM call `on_signal` on the watcher thread, then the process
  /// exits with 128 + the signal number. Construct before starting other threads.
  explicit StudyInterrupt(std::function<void(int)> on_signal);
  /// Stops the watcher; signals act as before again.
  ~StudyInterrupt();

 private:
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

}  // namespace lookahead::app
