// SPDX-License-Identifier: MIT
// Errors out of OpenMP regions. An exception that leaves a parallel region, a task or a
// single block calls std::terminate (OpenMP 5.0 sec. 2.1: a throw inside a structured block
// must be caught by the same thread in the same region), so no error handler ever sees it.
// Every `#pragma omp parallel` body runs through ParallelErrors::run: the first exception is
// kept, the iterations after it are skipped, and rethrow() raises it on the calling thread,
// after the region, where the caller's handler catches it like any other.
#pragma once

#include <atomic>
#include <exception>
#include <mutex>

namespace lookahead::slam {

class ParallelErrors {
 public:
  /// Calls body() unless an earlier call failed; keeps the first exception body() throws.
  template <class Body>
  void run(Body&& body) noexcept {
    if (failed_.load(std::memory_order_relaxed)) return;
    try {
      body();
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!first_) first_ = std::current_exception();
      failed_.store(true, std::memory_order_relaxed);
    }
  }

  [[nodiscard]] bool failed() const { return failed_.load(std::memory_order_relaxed); }

  /// Rethrows the first kept exception; call on the thread that opened the region, after it.
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::atomic<bool> failed_{false};
  std::mutex mutex_;
  std::exception_ptr first_;
};

}  // namespace lookahead::slam
