// The executables' parallel-for (app/process/parallel_for.h), the one that core's parallel paths run on: every index
// once, on several threads, the first exception rethrown after every thread has finished, and nesting. ./setup.sh
// test runs it under ThreadSanitizer too (ctest -L threads in build-tsan/).
#include "app/process/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace skinlayer {
namespace {

// The helpers start before the calling thread takes its first index, and on a loaded machine (ThreadSanitizer, two
// cores) they can take all 2000 before it does. So a helper holds its index until the calling thread has run one:
// then every index runs, and the calling thread is among the threads. A parallel-for whose calling thread does not
// work never returns here, and the test runs into ctest's timeout instead of passing.
TEST(ParallelFor, RunsEveryIndexOnceOnSeveralThreads) {
  constexpr int kCount = 2000;
  std::vector<std::atomic<int>> runs(kCount);
  std::mutex mutex;
  std::set<std::thread::id> threads;
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> caller_ran{false};
  parallel_for_threads(kCount, [&](int index) {
    ++runs[static_cast<std::size_t>(index)];
    {
      const std::lock_guard lock(mutex);
      threads.insert(std::this_thread::get_id());
    }
    if (std::this_thread::get_id() == caller) {
      caller_ran = true;
      caller_ran.notify_all();
      return;
    }
    caller_ran.wait(false);
  });
  for (int index = 0; index < kCount; ++index) EXPECT_EQ(runs[static_cast<std::size_t>(index)].load(), 1) << index;
  EXPECT_TRUE(caller_ran.load()) << "the calling thread works too";
  EXPECT_LE(threads.size(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST(ParallelFor, NoIndexRunsNothingAndOneRunsOnTheCallingThread) {
  int calls = 0;
  parallel_for_threads(0, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
  std::thread::id ran_on;
  parallel_for_threads(1, [&](int) { ran_on = std::this_thread::get_id(); });
  EXPECT_EQ(ran_on, std::this_thread::get_id());
}

TEST(ParallelFor, RethrowsTheFirstExceptionAfterEveryIndexHasRun) {
  constexpr int kCount = 64;
  std::atomic<int> finished{0};
  EXPECT_THROW(parallel_for_threads(kCount,
                                    [&](int index) {
                                      if (index % 16 == 3) throw std::runtime_error("index " + std::to_string(index));
                                      ++finished;
                                    }),
               std::runtime_error);
  EXPECT_EQ(finished.load(), kCount - 4) << "the other indices still ran, and all had ended before the rethrow";
}

// The solver nests them (RGB channels side by side, each with its kernels side by side): a body may call it again.
TEST(ParallelFor, BodiesMayRunAParallelForOfTheirOwn) {
  std::atomic<int> inner{0};
  parallel_for_threads(8, [&](int) { parallel_for_threads(50, [&](int) { ++inner; }); });
  EXPECT_EQ(inner.load(), 8 * 50);
}

}  // namespace
}  // namespace skinlayer
