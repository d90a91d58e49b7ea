// SPDX-License-Identifier: MIT
#include "study_interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <ctime>

namespace lookahead::app {
namespace {

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

StudyInterrupt::StudyInterrupt(std::function<void(int)> on_signal) {
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);  // inherited by every thread started later
  watcher_ = std::thread([this, set, on_signal = std::move(on_signal)] {
    const timespec poll{0, 200'000'000};  // how soon the destructor is noticed
    while (!done_) {
      const int sig = sigtimedwait(&set, nullptr, &poll);
      if (sig <= 0) continue;
      on_signal(sig);
      _exit(128 + sig);  // the workers are still in their missions: do not unwind them
    }
  });
}

StudyInterrupt::~StudyInterrupt() {
  done_ = true;
  watcher_.join();
  const sigset_t set = interrupt_signals();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

}  // namespace lookahead::app
