#include "anchorbench/engine/executor.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace anchorbench::engine {
namespace {

TEST(ParallelFor, RunsEveryItemOnceWithAThreadIndexInRange) {
  for (int threads : {1, 2, 4}) {
    std::vector<std::atomic<int>> runs(100);
    std::atomic<bool> thread_in_range{true};
    ParallelFor(100, threads, [&](int item, int thread) {
      ++runs[static_cast<std::size_t>(item)];
      if (thread < 0 || thread >= threads) thread_in_range = false;
    });
    for (const std::atomic<int>& count : runs) EXPECT_EQ(count.load(), 1) << threads << " threads";
    EXPECT_TRUE(thread_in_range.load());
  }
}

// Whatever the timing, the error rethrown is the first in item order: an error never keeps an
// earlier item from running.
TEST(ParallelFor, RethrowsTheFirstErrorInItemOrder) {
  for (int threads : {1, 2, 4}) {
    try {
      ParallelFor(50, threads, [](int item, int) {
        if (item == 7 || item == 30) throw std::runtime_error("item " + std::to_string(item));
      });
      ADD_FAILURE() << "no error";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "item 7") << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace anchorbench::engine
