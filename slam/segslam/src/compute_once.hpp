// SPDX-License-Identifier: MIT
// A value computed once per key by whichever thread asks first, while threads asking for the
// same key meanwhile wait for it instead of computing it again.
//
// Why: SegSLAM's particles ask for the same re-entry searches in one update (the match cache);
// without it two threads may both run a search the other is already running.
#pragma once

#include <future>
#include <map>
#include <mutex>
#include <utility>

namespace lookahead::slam::segslam {

/// The value of `key` in `cache`, made by `make()` if no thread has asked for it yet; sets
/// `*computed` when this call made it. An exception from `make` reaches every waiter.
/// Deadlock-free as long as `make` only waits on values whose makers wait on nothing it holds.
template <class Key, class Value, class Make>
Value compute_once(std::map<Key, std::shared_future<Value>>& cache, std::mutex& mutex, const Key& key, Make&& make,
                   bool* computed = nullptr) {
  std::promise<Value> promise;
  std::shared_future<Value> future;
  bool mine = false;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    const auto it = cache.find(key);
    if (it != cache.end()) {
      future = it->second;
    } else {
      future = promise.get_future().share();
      cache.emplace(key, future);
      mine = true;
    }
  }
  if (mine) {
    try {
      promise.set_value(make());
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  if (computed) *computed = mine;
  return future.get();
}

}  // namespace lookahead::slam::segslam
