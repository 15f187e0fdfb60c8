#include "anchorbench/engine/executor.hpp"

#include <atomic>
#include <exception>

namespace anchorbench::engine {

void LocalExecutor::Compute(const Plan& plan, const std::vector<int>& chunks, int threads, const ChunkDone& done) {
  const int count = static_cast<int>(chunks.size());
  std::exception_ptr first_error;
  int first_error_at = count;
  std::atomic<bool> failed{false};
#pragma omp parallel num_threads(threads)
  {
    // One sample buffer per thread, reused from unit to unit (megabytes per realization).
    std::vector<estimator::RangeSample> samples;
#pragma omp for schedule(dynamic, 1)
    for (int i = 0; i < count; ++i) {
      const int chunk = chunks[static_cast<std::size_t>(i)];
      if (failed.load(std::memory_order_relaxed)) continue;  // an error ends the call: no new chunk starts
      // An exception must leave neither a critical section nor the parallel region (both end in
      // std::terminate): each is caught where it is thrown and kept.
      std::exception_ptr error;
      try {
        ChunkResult result = ComputeChunk(plan, chunk, components_, samples);
        const std::string text = ChunkText(plan, chunk, result);
#pragma omp critical(anchorbench_chunk_done)
        {
          try {
            done(chunk, std::move(result), text);
          } catch (...) {
            error = std::current_exception();
          }
        }
      } catch (...) {
        error = std::current_exception();
      }
      if (error) {
        failed.store(true, std::memory_order_relaxed);
#pragma omp critical(anchorbench_chunk_error)
        if (i < first_error_at) {  // the first in list order, whatever the timing
          first_error_at = i;
          first_error = error;
        }
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace anchorbench::engine
