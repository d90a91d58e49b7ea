// SPDX-License-Identifier: MIT
#include "compute_once.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace lookahead::slam::segslam {
namespace {

// Threads asking for one key at once: one makes it, the others wait and get the same value.
TEST(ComputeOnce, ConcurrentAsksForOneKeyMakeItOnce) {
  std::map<int, std::shared_future<int>> cache;
  std::mutex mutex;
  std::atomic<int> makes{0}, made_here{0};
  std::vector<std::thread> threads;
  std::vector<int> got(8, 0);
  for (int t = 0; t < 8; ++t) {
    threads.emplace_back([&, t] {
      bool computed = false;
      got[static_cast<std::size_t>(t)] = compute_once(
          cache, mutex, 7,
          [&] {
            ++makes;
            std::this_thread::sleep_for(std::chrono::milliseconds(30));  // others arrive meanwhile
            return 42;
          },
          &computed);
      made_here += computed;
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(makes.load(), 1);
  EXPECT_EQ(made_here.load(), 1);
  for (int v : got) EXPECT_EQ(v, 42);
  // Another key is made separately.
  EXPECT_EQ(compute_once(cache, mutex, 8, [] { return 5; }), 5);
  EXPECT_EQ(cache.size(), 2u);
}

TEST(ComputeOnce, AFailedMakeReachesEveryAsker) {
  std::map<int, std::shared_future<int>> cache;
  std::mutex mutex;
  EXPECT_THROW(compute_once(cache, mutex, 1, []() -> int { throw std::runtime_error("no"); }), std::runtime_error);
  EXPECT_THROW(compute_once(cache, mutex, 1, [] { return 3; }), std::runtime_error);  // the failure is kept
}

}  // namespace
}  // namespace lookahead::slam::segslam
