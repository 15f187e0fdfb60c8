#include "anchorbench/engine/executor.hpp"

#include <omp.h>

#include <atomic>
#include <exception>
#include <mutex>

namespace anchorbench::engine {

void ParallelFor(int count, int threads, const std::function<void(int, int)>& work, const StopFlag* stop) {
  std::exception_ptr first_error;
  std::atomic<int> first_error_at{count};
  std::mutex error_mutex;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < count; ++i) {
    // An error ends the loop for the items after it only: an earlier item still runs, so the
    // first throwing item always runs and its error is the one rethrown, whatever the timing.
    if (i > first_error_at.load(std::memory_order_relaxed)) continue;
    try {  // an exception must not leave the parallel region (std::terminate)
      ThrowIfStopped(stop);
      work(i, omp_get_thread_num());
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (i < first_error_at.load(std::memory_order_relaxed)) {
        first_error_at.store(i, std::memory_order_relaxed);
        first_error = std::current_exception();
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

void LocalExecutor::Compute(const Plan& plan, const std::vector<int>& chunks, int threads, const ChunkDone& done) {
  // One sample buffer per thread, reused from unit to unit (megabytes per realization).
  std::vector<std::vector<estimator::RangeSample>> samples(static_cast<std::size_t>(std::max(threads, 1)));
  std::mutex done_mutex;  // `done` sees one chunk at a time
  ParallelFor(static_cast<int>(chunks.size()), threads, [&](int i, int thread) {
    const int chunk = chunks[static_cast<std::size_t>(i)];
    ChunkResult result = ComputeChunk(plan, chunk, components_, samples[static_cast<std::size_t>(thread)], stop_);
    const std::string text = ChunkText(plan, chunk, result);
    const std::lock_guard<std::mutex> lock(done_mutex);
    done(chunk, std::move(result), text);
  }, stop_);
}

void ComputeUnitsHere(const UnitWork& work, const std::vector<int>& units, int threads, const UnitDone& done,
                      const StopFlag* stop) {
  std::mutex done_mutex;  // `done` sees one unit at a time
  ParallelFor(static_cast<int>(units.size()), threads, [&](int i, int) {
    const int unit = units[static_cast<std::size_t>(i)];
    std::string text = work.text_of(unit);
    const std::lock_guard<std::mutex> lock(done_mutex);
    done(unit, std::move(text));
  }, stop);
}

void Executor::ComputeUnits(const UnitWork& work, const std::vector<int>& units, int threads, const UnitDone& done) {
  ComputeUnitsHere(work, units, threads, done, nullptr);
}

}  // namespace anchorbench::engine
